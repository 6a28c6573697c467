#include "reference/collision_estimate.h"

#include "reference/hertz_impact.h"
#include "reference/two_body_contact.h"
#include "reference/viscoelastic_spheres.h"
#include "reference/wall_contact_theory.h"

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    CollisionEstimate
    estimate_wall_collision(const WallCollision &body)
    {
      const double      R      = body.radius;
      const double      E2     = body.modulus;
      const double      c      = body.velocity_unit;
      const double      v0     = body.speed * c;
      const double      mass   = body.mass;
      const double      C      = body.law_constant;
      const auto        theory = wall_contact_theory(body.sphere);
      CollisionEstimate estimate;
      try
        {
          const auto one_dof    = theory->elastic_impact(mass, v0, E2, R, C);
          estimate.contact_time = one_dof.contact_time;
          estimate.largest_load = one_dof.max_force / theory->force_unit(E2, R);
          estimate.largest_compression  = one_dof.max_compression;
          estimate.one_dof_contact_time = one_dof.contact_time * c / R;
          estimate.one_dof_delta_max    = one_dof.max_compression / R;
          // With Kelvin-Voigt viscosity: m xi'' + F + tau xi' F' = 0 (Schwager
          // 2007, eq. 4, and Ramírez et al. 1999, eq. 5, with A = tau), ended
          // when the force returns to zero.
          const double tau = body.relaxation_time;
          if (tau > 0.)
            {
              const auto viscous =
                theory->viscous_impact(mass, v0, E2, R, C, tau);
              estimate.one_dof_epsilon = viscous.epsilon;
              // The same collision ended where the overlap returns to zero
              // (the papers' criterion, admitting an attractive force).
              estimate.one_dof_epsilon_overlap =
                theory
                  ->viscous_impact(
                    mass, v0, E2, R, C, tau, EndCriterion::overlap)
                  .epsilon;
              // The same law while the contact grows, F(xi + tau xi') while
              // it shrinks (a tension-free edge).
              const auto law = theory->force_law(E2, R, C);
              estimate.one_dof_epsilon_unloading =
                collide(mass,
                        v0,
                        law,
                        kelvin_voigt_unloading_force(law, tau),
                        EndCriterion::force,
                        1e-12)
                  .epsilon;
              estimate.one_dof_contact_time = viscous.contact_time * c / R;
              estimate.one_dof_delta_max    = viscous.max_overlap / R;
            }
        }
      catch (const std::domain_error &)
        {
          // Beyond the disk's log law: no 1-DOF collision; the contact time
          // and load of Gerl & Zippelius' eq. 61.
          estimate.one_dof_contact_time      = std::nan("");
          estimate.one_dof_delta_max         = std::nan("");
          estimate.one_dof_epsilon           = std::nan("");
          estimate.one_dof_epsilon_overlap   = std::nan("");
          estimate.one_dof_epsilon_unloading = std::nan("");
          const double speed                 = body.speed;
          const double delta    = speed * R * std::sqrt(std::log(4. / speed));
          estimate.contact_time = M_PI * delta / v0;
          estimate.largest_compression = delta;
          estimate.largest_load        = delta / (R * std::log(4. * R / delta));
        }
      return estimate;
    }

    CollisionEstimate
    estimate_pair_collision(const PairCollision &pair)
    {
      // The relative motion of two bodies: the reduced mass on the pair's
      // law (docs/theory/two-body-law.md), with each body's own constant.
      const bool        sphere = pair.sphere;
      const double      R      = pair.radius;
      const double      c      = pair.velocity_unit;
      const double      v0     = pair.speed * c;
      const double      m1     = pair.mass;
      const double      m2     = pair.partner_mass;
      const auto       &body   = pair.body;
      const auto       &other  = pair.partner;
      const double      mu     = m1 * m2 / (m1 + m2); // the reduced mass
      CollisionEstimate estimate;
      OneDofImpact      one_dof;
      bool              within_law = true;
      try
        {
          one_dof = two_body_elastic_impact(sphere, mu, v0, body, other);
          estimate.one_dof_contact_time = one_dof.contact_time * c / R;
          estimate.one_dof_delta_max    = one_dof.max_compression / R;
        }
      catch (const std::domain_error &)
        {
          within_law = false;
          // Beyond the pair's law: the wall's estimate (Gerl & Zippelius 1999,
          // eq. 61) for the equivalent body (docs/theory/two-body-law.md) with
          // the reduced mass, or Hertz's (D = 0) for spheres; no 1-DOF values.
          const auto eq = equivalent_body(sphere, body, other);
          if (sphere)
            {
              const auto hertz =
                hertz_sphere_impact(mu, eq.modulus, eq.radius, v0);
              one_dof.max_compression = hertz.max_overlap;
              one_dof.max_force       = hertz.max_force;
              one_dof.contact_time    = hertz.contact_time;
            }
          else
            {
              // delta = delta_0 sqrt(L), delta_0 = v sqrt(mu / (pi E_eff)),
              // L = sum_i w_i 2 ln(4 R_i / a) at a^2 = 4 R_eff delta_0, and
              // F = pi E_eff delta / L at a^2 = 4 R_eff delta: for one body on
              // the wall eq. 61's delta = v R sqrt(ln(4 / v)) and its load;
              // for identical bodies twice its delta at its force.
              const auto log_sum = [&](const double a) {
                double L = 0.;
                for (const auto *b : {&body, &other})
                  if (std::isfinite(b->modulus))
                    L += eq.modulus / b->modulus * 2. *
                         std::log(4. * b->radius / a);
                return L;
              };
              const double delta_0 = v0 * std::sqrt(mu / (M_PI * eq.modulus));
              one_dof.max_compression =
                delta_0 *
                std::sqrt(log_sum(std::sqrt(4. * eq.radius * delta_0)));
              one_dof.max_force =
                M_PI * eq.modulus * one_dof.max_compression /
                log_sum(std::sqrt(4. * eq.radius * one_dof.max_compression));
              one_dof.contact_time = M_PI * one_dof.max_compression / v0;
            }
          estimate.one_dof_contact_time      = std::nan("");
          estimate.one_dof_delta_max         = std::nan("");
          estimate.one_dof_epsilon           = std::nan("");
          estimate.one_dof_epsilon_overlap   = std::nan("");
          estimate.one_dof_epsilon_unloading = std::nan("");
        }
      estimate.contact_time        = one_dof.contact_time;
      estimate.largest_compression = one_dof.max_compression;
      // The load of the body alone on a wall whose Hertz zone has the pair's
      // half-width a at the largest force.
      const double a =
        two_body_half_width(sphere, one_dof.max_force, body, other);
      estimate.largest_load =
        sphere ? 4. * std::pow(a / R, 3) / (3. * M_PI) : a * a / (4. * R * R);
      // Kelvin-Voigt with one relaxation time: the relative motion obeys
      // mu delta'' + F + tau delta' F' = 0 (each body's viscous force is tau
      // times the rate of its elastic force).
      const double tau = pair.relaxation_time;
      if (tau > 0. || pair.partner_relaxation_time > 0.)
        {
          estimate.one_dof_epsilon           = std::nan("");
          estimate.one_dof_epsilon_overlap   = std::nan("");
          estimate.one_dof_epsilon_unloading = std::nan("");
          if (within_law && tau == pair.partner_relaxation_time)
            {
              const auto law = two_body_force_law(sphere, body, other);
              const auto viscous =
                collide(mu, v0, law, tau, EndCriterion::force);
              estimate.one_dof_epsilon = viscous.epsilon;
              estimate.one_dof_epsilon_overlap =
                collide(mu, v0, law, tau, EndCriterion::overlap).epsilon;
              estimate.one_dof_epsilon_unloading =
                collide(mu,
                        v0,
                        law,
                        kelvin_voigt_unloading_force(law, tau),
                        EndCriterion::force)
                  .epsilon;
              estimate.one_dof_contact_time = viscous.contact_time * c / R;
              estimate.one_dof_delta_max    = viscous.max_overlap / R;
            }
        }
      return estimate;
    }
  } // namespace Reference
} // namespace DiskImpact
