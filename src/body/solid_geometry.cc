#include "body/solid_geometry.h"

#include "base/input_error.h"

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cmath>
#include <set>
#include <string>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The manifold id of the cells next to the surface.
    constexpr types::manifold_id transfinite_manifold_id = 3;

    /**
     * The part y >= 0 (if @p cut_y), z >= 0 (if @p cut_z) of the balanced
     * ball: its cells lie within one octant each. The surface gets a
     * spherical manifold, the cells next to it (with their planar faces) a
     * transfinite interpolation of it, as the whole ball has.
     */
    void
    create_ball_part(const Point<3>   &center,
                     const double      R,
                     const bool        cut_y,
                     const bool        cut_z,
                     Triangulation<3> &triangulation)
    {
      Triangulation<3> ball;
      GridGenerator::hyper_ball_balanced(ball, center, R);
      std::set<Triangulation<3>::active_cell_iterator> outside;
      for (const auto &cell : ball.active_cell_iterators())
        if ((cut_y && cell->center()[1] < 0.) ||
            (cut_z && cell->center()[2] < 0.))
          outside.insert(cell);
      GridGenerator::create_triangulation_with_removed_cells(ball,
                                                             outside,
                                                             triangulation);
      const double tolerance = 1e-10 * R;
      const auto   on_plane  = [&](const auto &face, const unsigned int d) {
        for (const unsigned int v : face->vertex_indices())
          if (std::abs(face->vertex(v)[d]) > tolerance)
            return false;
        return true;
      };
      triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && !(cut_y && on_plane(face, 1)) &&
              !(cut_z && on_plane(face, 2)))
            cell->set_all_manifold_ids(transfinite_manifold_id);
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            if (cut_y && on_plane(face, 1))
              face->set_boundary_id(BoundaryIds::symmetry);
            else if (cut_z && on_plane(face, 2))
              face->set_boundary_id(BoundaryIds::symmetry_z);
            else
              {
                face->set_boundary_id(BoundaryIds::curved);
                face->set_all_manifold_ids(curved_manifold_id);
              }
          }
      triangulation.set_manifold(curved_manifold_id,
                                 SphericalManifold<3>(center));
      TransfiniteInterpolationManifold<3> transfinite;
      transfinite.initialize(triangulation);
      triangulation.set_manifold(transfinite_manifold_id, transfinite);
    }

    /**
     * The disk of thickness H in 3D: the plane models' coarse disk (or
     * half disk) extruded along z over H (or H/2 from the mid-plane
     * z = 0 for the quarter) in layers about as thick as its cells are
     * wide.
     */
    void
    create_thick_disk(const BodyGeometry &geometry,
                      Triangulation<3>   &triangulation)
    {
      const double     R = geometry.radius(), H = geometry.thickness();
      const bool       quarter = geometry.has_symmetry_boundary();
      Triangulation<2> section;
      geometry.create_coarse_triangulation(section);
      const double height = quarter ? 0.5 * H : H;
      const auto   layers =
        static_cast<unsigned int>(std::max(1., std::round(height / (0.5 * R))));
      std::vector<double> z;
      for (unsigned int i = 0; i <= layers; ++i)
        z.push_back((quarter ? 0. : -0.5 * H) + height * i / layers);
      extrude_disk(geometry, section, z, triangulation);
    }
  } // namespace

  void
  extrude_disk(const BodyGeometry        &geometry,
               const Triangulation<2>    &section,
               const std::vector<double> &z,
               Triangulation<3>          &triangulation)
  {
    const double R         = geometry.radius();
    const bool   quarter   = geometry.has_symmetry_boundary();
    const double tolerance = 1e-10 * R;
    GridGenerator::extrude_triangulation(section, z, triangulation);
    const auto all_at = [&](const auto &face, const auto &distance) {
      for (const unsigned int v : face->vertex_indices())
        if (std::abs(distance(face->vertex(v))) > tolerance)
          return false;
      return true;
    };
    triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
    for (const auto &face : triangulation.active_face_iterators())
      if (face->at_boundary())
        {
          if (all_at(face, [&](const Point<3> &x) {
                return std::hypot(x[0] - R, x[1]) - R;
              }))
            {
              face->set_boundary_id(BoundaryIds::curved);
              face->set_all_manifold_ids(curved_manifold_id);
            }
          else if (all_at(face, [](const Point<3> &x) { return x[1]; }))
            face->set_boundary_id(BoundaryIds::symmetry);
          else if (quarter &&
                   all_at(face, [](const Point<3> &x) { return x[2]; }))
            face->set_boundary_id(BoundaryIds::symmetry_z);
          else
            face->set_boundary_id(BoundaryIds::flat_faces);
        }
    triangulation.set_manifold(curved_manifold_id,
                               CylindricalManifold<3>(Tensor<1, 3>(
                                                        {0., 0., 1.}),
                                                      Point<3>(R, 0., 0.)));
  }

  void
  create_solid_triangulation(const BodyGeometry &geometry,
                             Triangulation<3>   &triangulation,
                             const double        max_cells)
  {
    const double   R = geometry.radius();
    const Point<3> center(R, 0., 0.);
    if (geometry.body() == Body::disk)
      create_thick_disk(geometry, triangulation);
    else if (geometry.has_symmetry_plane_z())
      create_ball_part(
        center, R, geometry.has_symmetry_boundary(), true, triangulation);
    else
      {
        GridGenerator::hyper_ball_balanced(triangulation, center, R);
        for (const auto &face : triangulation.active_face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(BoundaryIds::curved);
      }
    const double n_cells = triangulation.n_global_active_cells() *
                           std::pow(8., geometry.global_refinements());
    require(n_cells <= max_cells,
            "Geometry: the body's mesh after " +
              std::to_string(geometry.global_refinements()) +
              " global refinements would have " + approximately(n_cells) +
              " cells, more than this machine's memory holds");
    triangulation.refine_global(geometry.global_refinements());
  }
} // namespace DiskImpact
