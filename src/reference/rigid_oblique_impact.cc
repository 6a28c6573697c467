#include "reference/rigid_oblique_impact.h"

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    RigidObliqueImpact
    rigid_oblique_impact(const double             mass,
                         const double             radius,
                         const double             inertia_factor,
                         const double             friction,
                         const double             normal_restitution,
                         const ObliqueVelocities &before)
    {
      if (!(mass > 0. && radius > 0. && inertia_factor > 0. &&
            friction >= 0. && normal_restitution >= 0. &&
            normal_restitution <= 1. && before.normal > 0.))
        throw std::invalid_argument(
          "rigid_oblique_impact: needs m, R, k > 0, mu >= 0, 0 <= e_n <= 1 "
          "and a normal velocity toward the wall");
      RigidObliqueImpact impact;
      const double       slip_rate = (1. + 1. / inertia_factor) / mass;
      const double       s         = before.tangential + radius * before.spin;
      impact.slip_before           = s;
      impact.normal_impulse = mass * (1. + normal_restitution) * before.normal;
      // The friction impulse that would stop the contact point, and the
      // most Coulomb allows.
      const double stopping = -s / slip_rate;
      const double largest  = friction * impact.normal_impulse;
      impact.sticks         = std::abs(stopping) <= largest;
      impact.tangential_impulse =
        impact.sticks ? stopping : std::copysign(largest, stopping);
      impact.slip_after = s + slip_rate * impact.tangential_impulse;
      // |s| falls linearly with the normal impulse while the point slides
      // (over J_t / mu of it).
      impact.friction_work = 0.5 * std::abs(impact.tangential_impulse) *
                             (std::abs(s) + std::abs(impact.slip_after));
      impact.after.normal = normal_restitution * before.normal;
      impact.after.tangential =
        before.tangential + impact.tangential_impulse / mass;
      impact.after.spin =
        before.spin + impact.tangential_impulse /
                        (inertia_factor * mass * radius);
      return impact;
    }
  } // namespace Reference
} // namespace DiskImpact
