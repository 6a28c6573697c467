#include "body/conforming_mesh.h"

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The mesh being built: vertices, quadrilaterals and boundary edges.
    struct MeshData
    {
      std::vector<Point<2>>    vertices;
      std::vector<CellData<2>> cells;
      SubCellData              boundary;
      /// Each edge's midpoint, by the edge's (line's) index.
      std::map<unsigned int, unsigned int> midpoints;

      unsigned int
      add_vertex(const Point<2> &x)
      {
        vertices.push_back(x);
        return vertices.size() - 1;
      }

      unsigned int
      midpoint(const TriaIterator<TriaAccessor<1, 2, 2>> &line)
      {
        const auto [it, added] =
          midpoints.emplace(line->index(), vertices.size());
        if (added)
          vertices.push_back(line->center(/*respect_manifold=*/true));
        return it->second;
      }

      /// The quadrilateral a, b, c, d counterclockwise.
      void
      add_quad(const unsigned int a,
               const unsigned int b,
               const unsigned int c,
               const unsigned int d)
      {
        CellData<2> cell;
        cell.vertices = {a, b, d, c}; // deal.II's lexicographic order
        cells.push_back(cell);
      }
    };

    /// A cell's boundary counterclockwise: its vertices, hanging ones
    /// included, and the edge from each to the next.
    struct Polygon
    {
      std::vector<unsigned int>                       points;
      std::vector<TriaIterator<TriaAccessor<1, 2, 2>>> edges;
    };

    Polygon
    polygon_of(const Triangulation<2>::active_cell_iterator &cell)
    {
      // Corners 0, 1, 3, 2 counterclockwise; face 2 runs from corner 0 to
      // 1, face 1 from 1 to 3, face 3 from 3 to 2, face 0 from 2 to 0.
      constexpr std::array<unsigned int, 4> corners = {{0, 1, 3, 2}};
      constexpr std::array<unsigned int, 4> faces   = {{2, 1, 3, 0}};
      Polygon                               polygon;
      for (unsigned int i = 0; i < 4; ++i)
        {
          const unsigned int start = cell->vertex_index(corners[i]);
          const auto         face  = cell->face(faces[i]);
          polygon.points.push_back(start);
          if (!face->has_children())
            {
              polygon.edges.push_back(face);
              continue;
            }
          const bool forward = face->vertex_index(0) == start;
          polygon.points.push_back(face->child(0)->vertex_index(1));
          polygon.edges.push_back(face->child(forward ? 0 : 1));
          polygon.edges.push_back(face->child(forward ? 1 : 0));
        }
      return polygon;
    }

    /// A cell without hanging nodes: its four children.
    void
    split_regular(const Triangulation<2>::active_cell_iterator &cell,
                  const Polygon                                &polygon,
                  MeshData                                     &mesh)
    {
      const unsigned int centre = mesh.add_vertex(cell->center(true));
      for (unsigned int i = 0; i < 4; ++i)
        mesh.add_quad(polygon.points[i],
                      mesh.midpoint(polygon.edges[i]),
                      centre,
                      mesh.midpoint(polygon.edges[(i + 3) % 4]));
    }

    /// A cell with hanging nodes: triangles fanned from the centre, each
    /// split into three quadrilaterals.
    void
    split_with_hanging_nodes(const Triangulation<2>::active_cell_iterator &cell,
                             const Polygon &polygon,
                             MeshData      &mesh)
    {
      const unsigned int n      = polygon.points.size();
      const Point<2>     c      = cell->center(true);
      const unsigned int centre = mesh.add_vertex(c);
      std::vector<unsigned int> spokes(n);
      for (unsigned int i = 0; i < n; ++i)
        spokes[i] = mesh.add_vertex(
          Point<2>(0.5 * (c + mesh.vertices[polygon.points[i]])));
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int j = (i + 1) % n;
          const unsigned int p = polygon.points[i], q = polygon.points[j];
          const unsigned int m = mesh.midpoint(polygon.edges[i]);
          const unsigned int centroid = mesh.add_vertex(
            Point<2>((c + mesh.vertices[p] + mesh.vertices[q]) / 3.));
          mesh.add_quad(p, m, centroid, spokes[i]);
          mesh.add_quad(q, spokes[j], centroid, m);
          mesh.add_quad(centre, spokes[i], centroid, spokes[j]);
        }
    }

    /// A boundary edge's two halves, with its boundary and manifold ids.
    void
    add_boundary_halves(const TriaIterator<TriaAccessor<1, 2, 2>> &face,
                        MeshData                                  &mesh)
    {
      const unsigned int middle = mesh.midpoint(face);
      for (const unsigned int end : {face->vertex_index(0),
                                     face->vertex_index(1)})
        {
          CellData<1> line;
          line.vertices    = {end, middle};
          line.boundary_id = face->boundary_id();
          line.manifold_id = face->manifold_id();
          mesh.boundary.boundary_lines.push_back(line);
        }
    }
  } // namespace

  void
  split_into_conforming_mesh(const Triangulation<2> &refined,
                             Triangulation<2>       &conforming)
  {
    MeshData mesh;
    mesh.vertices = refined.get_vertices();
    for (const auto &cell : refined.active_cell_iterators())
      {
        const Polygon polygon = polygon_of(cell);
        if (polygon.points.size() == 4)
          split_regular(cell, polygon, mesh);
        else
          split_with_hanging_nodes(cell, polygon, mesh);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            add_boundary_halves(face, mesh);
      }
    GridTools::delete_unused_vertices(mesh.vertices,
                                      mesh.cells,
                                      mesh.boundary);
    GridTools::consistently_order_cells(mesh.cells);
    conforming.create_triangulation(mesh.vertices, mesh.cells, mesh.boundary);
    for (const types::manifold_id id : refined.get_manifold_ids())
      if (id != numbers::flat_manifold_id)
        conforming.set_manifold(id, refined.get_manifold(id));
  }

  std::vector<double>
  layers_graded_toward_face(const double height,
                            const double finest,
                            const double grading,
                            const double fine_zone,
                            const double largest)
  {
    std::vector<double> thicknesses;
    double              depth = 0.;
    while (depth < height * (1. - 1e-12))
      {
        const double layer = std::min(
          largest, finest + grading * std::max(0., depth - fine_zone));
        thicknesses.push_back(layer);
        depth += layer;
      }
    // Scale the layers to fill the height; z runs from 0 to the face.
    std::vector<double> z = {height};
    for (const double layer : thicknesses)
      z.push_back(z.back() - layer * height / depth);
    z.back() = 0.;
    std::reverse(z.begin(), z.end());
    return z;
  }
} // namespace DiskImpact
