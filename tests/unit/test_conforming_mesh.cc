// The graded mesh halved without hanging nodes, and the layers a disk in
// 3D is extruded through.

#include "body/conforming_mesh.h"
#include "body/geometry.h"
#include "half_disk.h"
#include "impact/impact_mesh.h"
#include "run/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <utility>

using namespace DiskImpact;

namespace
{
  /// The half disk graded toward the contact point (half-width 0.1,
  /// 3 elements across, grading 0.6): cells of four levels, hanging nodes.
  void
  graded_half_disk(dealii::Triangulation<2> &triangulation)
  {
    const BodyGeometry geometry = half_disk(1);
    geometry.create_triangulation(triangulation);
    refine_toward_contact(
      triangulation, geometry.contact_point(), 0.1, 3, 0.6, 1.5);
  }

  /// The length of the boundary with boundary id @p id, edge by edge.
  double
  boundary_length(const dealii::Triangulation<2> &triangulation,
                  const dealii::types::boundary_id id)
  {
    double length = 0.;
    for (const auto &face : triangulation.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == id)
        length += face->measure();
    return length;
  }

  /// The smallest interior angle of a cell [rad].
  double
  smallest_angle(const dealii::Triangulation<2>::active_cell_iterator &cell)
  {
    constexpr unsigned int corners[4] = {0, 1, 3, 2}; // counterclockwise
    double                 smallest   = M_PI;
    for (unsigned int i = 0; i < 4; ++i)
      {
        const auto p = cell->vertex(corners[i]);
        const auto a = cell->vertex(corners[(i + 1) % 4]) - p;
        const auto b = cell->vertex(corners[(i + 3) % 4]) - p;
        smallest     = std::min(smallest,
                            std::acos(a * b / (a.norm() * b.norm())));
      }
    return smallest;
  }
} // namespace

TEST_CASE("the halved graded mesh is conforming and keeps the boundary",
          "[geometry]")
{
  dealii::Triangulation<2> graded(
    dealii::Triangulation<2>::limit_level_difference_at_vertices);
  graded_half_disk(graded);
  REQUIRE(graded.n_levels() >= 4);
  dealii::Triangulation<2> conforming;
  split_into_conforming_mesh(graded, conforming);

  // A hanging node left would make its two sides interior boundaries:
  // the boundary is the symmetry line (length 2) and the half circle,
  // whose chords on twice as many edges are closer to pi.
  const double line = boundary_length(conforming, BoundaryIds::symmetry);
  const double arc  = boundary_length(conforming, BoundaryIds::curved);
  CHECK(line == Approx(2.).epsilon(1e-13));
  CHECK(arc < M_PI);
  CHECK(arc > boundary_length(graded, BoundaryIds::curved));
  double total = 0.;
  for (const auto &face : conforming.active_face_iterators())
    if (face->at_boundary())
      total += face->measure();
  CHECK(total == Approx(line + arc).epsilon(1e-13));

  // Every cell has positive area and no flat corner; the area is the
  // graded mesh's plus the slivers the midpoints on the circle add.
  double area = 0., graded_area = 0.;
  for (const auto &cell : conforming.active_cell_iterators())
    {
      CHECK(cell->measure() > 0.);
      CHECK(smallest_angle(cell) > 0.25 * M_PI / 2.);
      area += cell->measure();
    }
  for (const auto &cell : graded.active_cell_iterators())
    graded_area += cell->measure();
  CHECK(area > graded_area);
  CHECK(area < M_PI / 2.);

  // Every cell is at most half its parent's size: the finest zone's cells
  // are at most half the graded mesh's finest.
  double finest_graded = 1., finest_conforming = 1.;
  for (const auto &cell : graded.active_cell_iterators())
    finest_graded = std::min(finest_graded, cell->diameter());
  for (const auto &cell : conforming.active_cell_iterators())
    finest_conforming = std::min(finest_conforming, cell->diameter());
  CHECK(finest_conforming <= 0.5 * finest_graded * (1. + 1e-12));
  CHECK(conforming.n_active_cells() >= 4 * graded.n_active_cells());
}

TEST_CASE("the layers thicken away from the face as the grading says",
          "[geometry]")
{
  const double height = 1., finest = 0.01, grading = 0.5, zone = 0.02,
               largest = 0.2;
  const auto z =
    layers_graded_toward_face(height, finest, grading, zone, largest);
  REQUIRE(z.size() > 3);
  CHECK(z.front() == 0.);
  CHECK(z.back() == height);
  // The layers' thicknesses before the common scaling: finest within the
  // zone, then finest + grading * depth, at most the largest.
  double depth = 0., total = 0.;
  std::vector<double> unscaled;
  while (depth < height * (1. - 1e-12))
    {
      unscaled.push_back(
        std::min(largest, finest + grading * std::max(0., depth - zone)));
      depth += unscaled.back();
    }
  for (const double t : unscaled)
    total += t;
  REQUIRE(z.size() == unscaled.size() + 1);
  for (unsigned int i = 0; i < unscaled.size(); ++i)
    CHECK(z[z.size() - 1 - i] - z[z.size() - 2 - i] ==
          Approx(unscaled[i] * height / total).epsilon(1e-12));
  CHECK(total >= height);
  CHECK(total < height + largest);
}

namespace
{
  /// The impact mesh of the quarter of a free disk (H = R, v = 0.1c) in 3D
  /// on the conforming mesh: 'Global refinements', 'Elements across
  /// contact', 'Grading' of @p level (4 across, grading 0.6 at 0, each
  /// level halving) and 'Layer refinement' @p layers.
  dealii::Triangulation<3>
  thick_disk_mesh(const unsigned int level, const int layers)
  {
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.parse_input_from_string(
      "set Task = impact\n"
      "subsection Geometry\n"
      "  set Dimension = 3\n"
      "  set Thickness = 1\n"
      "  set Faces = free\n"
      "  set Global refinements = " +
      std::to_string(level) +
      "\n"
      "end\n"
      "subsection Impact\n"
      "  set Velocity = 0.1\n"
      "  set Graded mesh = conforming\n"
      "  set Elements across contact = " +
      std::to_string(4 << level) +
      "\n  set Grading = " + std::to_string(0.6 / (1 << level)) +
      "\n  set Layer refinement = " + std::to_string(layers) + "\nend\n");
    Parameters parameters;
    parameters.parse_parameters(prm);
    dealii::Triangulation<3> mesh;
    create_impact_mesh(parameters, mesh);
    return mesh;
  }

  /// The planes z of a mesh's vertices and its cells per layer.
  std::pair<std::set<double>, unsigned int>
  layers_and_section(const dealii::Triangulation<3> &mesh)
  {
    std::set<double> z;
    for (const auto &vertex : mesh.get_vertices())
      z.insert(std::round(vertex[2] * 1e10) / 1e10);
    return {z, mesh.n_active_cells() / (z.size() - 1)};
  }
} // namespace

TEST_CASE("a disk's section and its layers refine apart", "[geometry]")
{
  // The mesh of the next level in parts: its section with the layers of
  // this level (Layer refinement -1), and this level's section with the
  // next level's layers (+1).
  const auto base          = layers_and_section(thick_disk_mesh(0, 0));
  const auto next          = layers_and_section(thick_disk_mesh(1, 0));
  const auto section_alone = layers_and_section(thick_disk_mesh(1, -1));
  const auto layers_alone  = layers_and_section(thick_disk_mesh(0, 1));
  REQUIRE(next.first.size() > base.first.size());
  REQUIRE(next.second > base.second);
  CHECK(section_alone.first == base.first);
  CHECK(section_alone.second == next.second);
  CHECK(layers_alone.first == next.first);
  CHECK(layers_alone.second == base.second);
}
