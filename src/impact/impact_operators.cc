#include "impact/impact_operators.h"

#include "body/geometry.h"
#include "contact/contact_operator.h"
#include "impact/impact_estimates.h"
#include "impact/impact_mesh.h"
#include "run/parameters.h"

#include <algorithm>
#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  template <int dim>
  ImpactOperators<dim>::ImpactOperators(const Parameters &parameters,
                                        MPI_Comm          communicator)
      : triangulation(communicator,
                      Triangulation<dim>::limit_level_difference_at_vertices)
      , op(parameters.finite_element.degree)
  {
    const auto  &geometry = parameters.geometry;
    const double R        = geometry.radius();
    const double largest_half_width =
      DiskImpact::largest_half_width(parameters);
    create_impact_mesh(parameters, triangulation);
    op.setup(triangulation, geometry, false);
    // Two bodies: the penalty k = kappa E / h with the pair's modulus
    // 1 / E = 1 / E2 + 1 / E2' (the wall's with identical bodies, whose gap
    // is twice the wall's).
    law = parameters.contact.law({contact_modulus(parameters),
                                  smallest_edge_face(op, !geometry.is_sphere()),
                                  R});
    // The candidates: edge points whose undeformed gap is below the law's
    // reach plus three times the largest approach the 1-DOF model expects,
    // or a plastic body's bound of it (or the Hertz zone's own gap
    // a^2 / 2R, if larger).
    const double approach =
      std::max(estimate_collision(parameters).largest_compression,
               plastic_approach_bound(parameters));
    // A turning body's contact moves along its edge (contact_drift()).
    const double reach = largest_half_width + contact_drift(parameters);
    candidate_bound    = (law ? law->reach() : 0.) +
                      3. * std::max(approach, reach * reach / (2. * R));
    // No inertia on the edge within the uniformly refined contact zone;
    // with the constraint, on all the candidates' faces (their undeformed
    // gap t^2 / 2R is below the bound).
    if (parameters.contact.exact_constraint())
      op.set_massless_edge_zone(embedded<dim>(geometry.contact_point()),
                                1.5 * std::max(largest_half_width,
                                               std::sqrt(2. * R *
                                                         candidate_bound)));
    else if (parameters.time_integrator.redistribute_mass())
      op.set_massless_edge_zone(embedded<dim>(geometry.contact_point()),
                                1.5 * largest_half_width);
    op.assemble(materials(parameters));
    constraint_map = std::make_unique<ConstraintMap>(op.get_constraints(),
                                                     op.locally_owned_dofs(),
                                                     communicator);
    mass_product   = std::make_unique<InterleavedMass>(op.mass_matrix(),
                                                     op.get_constraints(),
                                                     *constraint_map);
  }

  std::vector<Material>
  ImpactOperatorsBase::materials(const Parameters &parameters)
  {
    if (parameters.partner.is_body())
      return {parameters.material, parameters.partner.material()};
    return {parameters.material};
  }

  std::shared_ptr<ImpactOperatorsBase>
  make_impact_operators(const Parameters &parameters, MPI_Comm communicator)
  {
    if (parameters.geometry.dimension() == 3)
      return std::make_shared<ImpactOperators<3>>(parameters, communicator);
    return std::make_shared<ImpactOperators<2>>(parameters, communicator);
  }

  template struct ImpactOperators<2>;
  template struct ImpactOperators<3>;
} // namespace DiskImpact
