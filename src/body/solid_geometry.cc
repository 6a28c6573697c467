#include "body/solid_geometry.h"

#include "base/input_error.h"

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <string>

namespace DiskImpact
{
  using namespace dealii;

  double
  solid_sphere_cells(const unsigned int refinements)
  {
    return 32. * std::pow(8., refinements);
  }

  void
  create_solid_triangulation(const BodyGeometry &geometry,
                             Triangulation<3>   &triangulation,
                             const double        max_cells)
  {
    const double R = geometry.radius();
    require(solid_sphere_cells(geometry.global_refinements()) <= max_cells,
            "Geometry: the sphere's mesh after " +
              std::to_string(geometry.global_refinements()) +
              " global refinements would have " +
              approximately(solid_sphere_cells(geometry.global_refinements())) +
              " cells, more than this machine's memory holds");
    GridGenerator::hyper_ball_balanced(triangulation, Point<3>(R, 0., 0.), R);
    for (const auto &face : triangulation.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(BoundaryIds::curved);
    triangulation.refine_global(geometry.global_refinements());
  }
} // namespace DiskImpact
