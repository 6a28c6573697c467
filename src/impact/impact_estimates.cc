#include "impact/impact_estimates.h"

#include "base/input_error.h"
#include "reference/hertz_impact.h"
#include "reference/sphere_finite_size.h"
#include "reference/viscoelastic_spheres.h"
#include "run/parameters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace DiskImpact
{
  namespace
  {
    /// estimate_collision() of two bodies (subsection Partner).
    CollisionEstimate
    estimate_pair_collision(const Parameters &parameters)
    {
      const auto &partner      = parameters.partner;
      const auto [body, other] = contact_bodies(parameters);
      return Reference::estimate_pair_collision(
        {parameters.geometry.is_sphere(),
         parameters.material.density() * parameters.geometry.volume(),
         partner.material().density() *
           parameters.geometry.with_radius(partner.radius()).volume(),
         parameters.impact.normal_velocity(),
         parameters.material.velocity_unit(),
         parameters.geometry.radius(),
         body,
         other,
         parameters.material.relaxation_time(),
         partner.material().relaxation_time()});
    }

    /// A sphere's impact as one body on the wall: its mass and contact
    /// body (radius, E*), or the pair's reduced mass and equivalent body.
    std::pair<double, Reference::ContactBody>
    wall_equivalent_sphere(const Parameters &parameters)
    {
      const auto &material = parameters.material;
      double      mass     = material.density() * parameters.geometry.volume();
      Reference::ContactBody body{parameters.geometry.radius(),
                                  material.in_plane_young_modulus(),
                                  0.};
      const auto            &partner = parameters.partner;
      if (partner.is_body())
        {
          const double m2 =
            partner.material().density() *
            parameters.geometry.with_radius(partner.radius()).volume();
          mass = mass * m2 / (mass + m2);
          body = Reference::equivalent_body(
            true,
            body,
            {partner.radius(),
             partner.material().in_plane_young_modulus(),
             0.});
        }
      return {mass, body};
    }
  } // namespace

  double
  one_dof_law_constant(const Parameters &parameters)
  {
    if (parameters.impact.finite_size_law_constant())
      return finite_size_constant(parameters, hertz_contact_radius(parameters));
    return parameters.impact.fixed_law_constant(
      parameters.material.in_plane_poisson_ratio(),
      parameters.geometry.is_sphere());
  }

  double
  hertz_contact_radius(const Parameters &parameters)
  {
    // Hertz's impact of the sphere on the wall, or of the pair as its
    // equivalent body with the reduced mass; a^2 = R_eff delta_max.
    const double v0 =
      parameters.impact.normal_velocity() * parameters.material.velocity_unit();
    const auto [mass, body] = wall_equivalent_sphere(parameters);
    return std::sqrt(
      body.radius *
      Reference::hertz_sphere_impact(mass, body.modulus, body.radius, v0)
        .max_overlap);
  }

  double
  plastic_approach_bound(const Parameters &parameters)
  {
    const auto &material = parameters.material;
    const auto &partner  = parameters.partner;
    double      yield    = std::numeric_limits<double>::infinity();
    if (material.is_plastic())
      yield = material.yield_stress();
    if (partner.is_body() && partner.material().is_plastic())
      yield = std::min(yield, partner.material().yield_stress());
    if (!std::isfinite(yield) || !parameters.geometry.is_sphere())
      return 0.;
    const double v0 =
      parameters.impact.normal_velocity() * material.velocity_unit();
    const auto [mass, body] = wall_equivalent_sphere(parameters);
    return v0 * std::sqrt(mass / (M_PI * body.radius * yield));
  }

  double
  finite_size_constant(const Parameters &body, const double contact_radius)
  {
    require(body.geometry.is_sphere(),
            "Impact: 'One-DOF law constant = finite size' is the sphere's "
            "law; a disk takes 'exact', 'fit' or a number");
    // D = D0 + D1 ln(a/R) (docs/theory/sphere-finite-size.md).
    return Reference::sphere_finite_size_term(
      Reference::sphere_finite_size_constants(body.material.poisson_ratio()),
      contact_radius / body.geometry.radius());
  }

  void
  check_impact_time_step(const Parameters &parameters)
  {
    parameters.time_integrator.check_time_step(
      estimate_collision(parameters).contact_time);
  }

  double
  contact_drift(const Parameters &parameters)
  {
    const double R     = parameters.geometry.radius();
    const double c     = parameters.material.velocity_unit();
    const auto  &im    = parameters.impact;
    const double slide = std::abs(im.tangential_velocity() - im.spin());
    // Friction changes omega R by at most mu v_n (1 + epsilon) / k, and by
    // at most 2 |v_t - omega0 R| / (1 + k) if the contact point stops and
    // reverses (k = I / (m R^2): 1/2 a disk, 2/5 a sphere).
    const double k = parameters.geometry.is_sphere() ? 0.4 : 0.5;
    const double spin_rate =
      (std::abs(im.spin()) +
       std::min(2. / k * parameters.contact.friction_coefficient() *
                  im.normal_velocity(),
                2. / (1. + k) * slide)) *
      c / R;
    return spin_rate == 0. ?
             0. :
             R * spin_rate * estimate_collision(parameters).contact_time;
  }

  CollisionEstimate
  estimate_collision(const Parameters &parameters)
  {
    if (parameters.partner.is_body())
      return estimate_pair_collision(parameters);
    const auto &material = parameters.material;
    return Reference::estimate_wall_collision(
      {parameters.geometry.is_sphere(),
       material.density() * parameters.geometry.volume(),
       parameters.impact.normal_velocity(),
       material.velocity_unit(),
       material.in_plane_young_modulus(),
       parameters.geometry.radius(),
       one_dof_law_constant(parameters),
       material.relaxation_time()});
  }

  std::pair<Reference::ContactBody, Reference::ContactBody>
  contact_bodies(const Parameters &parameters)
  {
    const auto &partner      = parameters.partner;
    Parameters  partner_only = parameters;
    partner_only.material    = partner.material();
    partner_only.geometry = parameters.geometry.with_radius(partner.radius());
    return {{parameters.geometry.radius(),
             parameters.material.in_plane_young_modulus(),
             one_dof_law_constant(parameters)},
            {partner.radius(),
             partner.material().in_plane_young_modulus(),
             parameters.impact.finite_size_law_constant() ?
               finite_size_constant(partner_only,
                                    hertz_contact_radius(parameters)) :
               one_dof_law_constant(partner_only)}};
  }

  double
  contact_modulus(const Parameters &parameters)
  {
    const double E2 = parameters.material.in_plane_young_modulus();
    if (!parameters.partner.is_body())
      return E2;
    const double E2_partner =
      parameters.partner.material().in_plane_young_modulus();
    return 1. / (1. / E2 + 1. / E2_partner);
  }

  double
  dissipation_parameter(const Parameters &parameters)
  {
    const auto  &material = parameters.material;
    const double R        = parameters.geometry.radius();
    const double E2       = material.in_plane_young_modulus();
    const double mass     = material.density() * parameters.geometry.volume();
    const double tau      = material.relaxation_time();
    if (!parameters.geometry.is_sphere())
      // Schwager's alpha = A sqrt(pi E2 / m) with A = tau (Schwager 2007).
      return tau * std::sqrt(M_PI * E2 / mass);
    // Ramírez et al.'s u = (v / g*)^{1/5} with A = tau, eq. 32.
    if (!(tau > 0.))
      return 0.;
    return Reference::sphere_scaled_velocity(
      mass,
      Reference::hertz_sphere_stiffness(E2, R),
      tau,
      parameters.impact.normal_velocity() * material.velocity_unit());
  }

  double
  force_unit(const Parameters &parameters)
  {
    const double R = parameters.geometry.radius();
    return parameters.material.in_plane_young_modulus() * R *
           (parameters.geometry.is_sphere() ? R : 1.);
  }

  std::string
  output_units(const Parameters &parameters)
  {
    return parameters.geometry.is_sphere() ?
             "lengths R, times R/c, velocities c = sqrt(E*/rho) with E* = "
             "E/(1-nu^2), forces E* R^2, energies E* R^3 (the whole sphere)" :
             "lengths R, times R/c, velocities c = sqrt(E2/rho), forces E2 "
             "R, energies E2 R^2 (per unit thickness)";
  }
} // namespace DiskImpact
