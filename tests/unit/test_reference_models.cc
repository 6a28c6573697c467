#include "reference/collision_ode.h"
#include "reference/linear_dashpot.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact::Reference;

namespace
{
  /// xi'' + 2 beta xi' + omega0^2 xi = 0 as the general ODE with m = 1:
  /// F = omega0^2 xi, A F' = 2 beta.
  Collision
  dashpot_ode(const double beta, const double omega0, const EndCriterion end)
  {
    const double k = omega0 * omega0;
    ForceLaw     law{[k](const double xi) { return k * xi; },
                 [k](double) { return k; }};
    return collide(1., 0.7, law, 2. * beta / k, end);
  }
} // namespace

TEST_CASE("Linear dashpot: eq. 21 (corrected) against the ODE",
          "[reference][dashpot]")
{
  const double omega0 = 1.3;
  // all three branches: below omega0/sqrt(2), up to omega0, above
  for (const double ratio : {0.05, 0.3, 0.7, 0.72, 0.9, 0.999, 1.2, 3., 10.})
    {
      const double beta = ratio * omega0;
      const auto   ode  = dashpot_ode(beta, omega0, EndCriterion::force);
      INFO("beta / omega0 = " << ratio);
      CHECK(std::abs(dashpot_restitution(beta, omega0) - ode.epsilon) <= 1e-10);
    }
}

TEST_CASE("Linear dashpot: the printed middle branch of eq. 21 is wrong",
          "[reference][dashpot]")
{
  const double omega0 = 1., beta = 0.85;
  CHECK(dashpot_restitution_printed_middle_branch(beta, omega0) > 1.);
  CHECK(dashpot_restitution(beta, omega0) < 1.);
}

TEST_CASE("Linear dashpot: the overlap criterion (eq. 15) and capture",
          "[reference][dashpot]")
{
  const double omega0 = 2.;
  for (const double ratio : {0.1, 0.5, 0.9})
    {
      const double beta = ratio * omega0;
      const auto   ode  = dashpot_ode(beta, omega0, EndCriterion::overlap);
      CHECK(std::abs(dashpot_restitution_overlap_criterion(beta, omega0) -
                     ode.epsilon) <= 1e-10);
      // the correct criterion ends earlier, with a larger epsilon
      CHECK(dashpot_restitution(beta, omega0) > ode.epsilon);
    }
  CHECK(dashpot_restitution_overlap_criterion(1.5 * omega0, omega0) == 0.);
}
