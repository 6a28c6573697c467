#include "impact/impact_mesh.h"

#include "body/solid_geometry.h"
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
    return Reference::wall_contact_theory(parameters.geometry.is_sphere())
             ->half_width(estimate_collision(parameters).largest_load) *
           parameters.geometry.radius();
  }

  namespace
  {
    /// The contact line's direction: a disk's rim in 3D touches the wall
    /// along z; zero (a contact point) otherwise.
    template <int dim>
    Tensor<1, dim>
    rim_direction(const BodyGeometry &geometry)
    {
      Tensor<1, dim> direction;
      if (dim == 3 && geometry.body() == Body::disk)
        direction[dim - 1] = 1.;
      return direction;
    }
  } // namespace

  template <int dim>
  void
  create_impact_mesh(const Parameters   &parameters,
                     Triangulation<dim> &triangulation,
                     const double        max_cells)
  {
    const auto &geometry = parameters.geometry;
    if constexpr (dim == 3)
      create_solid_triangulation(geometry, triangulation, max_cells);
    else if (parameters.partner.is_body())
      parameters.partner.create_pair_triangulation(geometry,
                                                   triangulation,
                                                   max_cells);
    else
      geometry.create_triangulation(triangulation, max_cells);
    refine_toward_contact(triangulation,
                          embedded<dim>(geometry.contact_point()),
                          graded_width(parameters),
                          parameters.impact.elements_across_contact(),
                          parameters.impact.grading(),
                          parameters.impact.fine_zone_radius(),
                          max_cells,
                          rim_direction<dim>(geometry));
  }

  template void
  create_impact_mesh(const Parameters &, Triangulation<2> &, double);
  template void
  create_impact_mesh(const Parameters &, Triangulation<3> &, double);
} // namespace DiskImpact
