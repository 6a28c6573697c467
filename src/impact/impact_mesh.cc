#include "impact/impact_mesh.h"

#include "impact/impact_estimates.h"
#include "reference/wall_contact_theory.h"
#include "run/parameters.h"

namespace DiskImpact
{
  using namespace dealii;

  double
  graded_width(const Parameters &parameters)
  {
    if (parameters.impact.graded_half_width() > 0.)
      return parameters.impact.graded_half_width() *
             parameters.geometry.radius();
    return largest_half_width(parameters);
  }

  double
  largest_half_width(const Parameters &parameters)
  {
    return Reference::wall_contact_theory(parameters.geometry.is_axisymmetric())
             ->half_width(estimate_collision(parameters).largest_load) *
           parameters.geometry.radius();
  }

  void
  create_impact_mesh(const Parameters &parameters,
                     Triangulation<2> &triangulation,
                     const double      max_cells)
  {
    const auto &geometry = parameters.geometry;
    if (parameters.partner.is_body())
      parameters.partner.create_pair_triangulation(geometry,
                                                   triangulation,
                                                   max_cells);
    else
      geometry.create_triangulation(triangulation, max_cells);
    refine_toward_contact(triangulation,
                          geometry.contact_point(),
                          graded_width(parameters),
                          parameters.impact.elements_across_contact(),
                          parameters.impact.grading(),
                          parameters.impact.fine_zone_radius(),
                          max_cells);
  }
} // namespace DiskImpact
