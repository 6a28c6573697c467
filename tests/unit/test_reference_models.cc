#include "reference/collision_ode.h"
#include "reference/linear_dashpot.h"
#include "reference/one_dof_impact.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact::Reference;

TEST_CASE("Linear dashpot: eq. 21 (corrected) against the ODE",
          "[reference][dashpot]")
{
  const double omega0 = 1.3;
  // all three branches: below omega0/sqrt(2), up to omega0, above
  for (const double ratio : {0.05, 0.3, 0.7, 0.72, 0.9, 0.999, 1.2, 3., 10.})
    {
      const double beta = ratio * omega0;
      const auto   ode  = dashpot_collision(beta, omega0, EndCriterion::force);
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
      const auto   ode = dashpot_collision(beta, omega0, EndCriterion::overlap);
      CHECK(std::abs(dashpot_restitution_overlap_criterion(beta, omega0) -
                     ode.epsilon) <= 1e-10);
      // the correct criterion ends earlier, with a larger epsilon
      CHECK(dashpot_restitution(beta, omega0) > ode.epsilon);
    }
  CHECK(dashpot_restitution_overlap_criterion(1.5 * omega0, omega0) == 0.);
}

TEST_CASE("Disk log law: the elastic ODE against the quadrature",
          "[reference][disk]")
{
  // m xi'' = -F(xi) with the log law, no dissipation: epsilon = 1 and the
  // contact time and largest overlap of one_dof_impact() (Gauss-Kronrod).
  const double mass = M_PI, E2 = 1., R = 1., C = -1.7437, v = 0.01;
  const auto   law = disk_force_law(E2, R, C);
  for (const auto end : {EndCriterion::force, EndCriterion::overlap})
    {
      const auto ode       = collide(mass, v, law, 0., end);
      const auto reference = one_dof_impact(v, mass, E2, R, C);
      CHECK(ode.epsilon == Approx(1.).epsilon(1e-9));
      CHECK(ode.contact_time == Approx(reference.contact_time).epsilon(1e-8));
      CHECK(ode.max_overlap == Approx(reference.max_compression).epsilon(1e-6));
    }
}

TEST_CASE("Disk log law: dissipation lowers epsilon, and the force criterion "
          "ends the collision first",
          "[reference][disk]")
{
  const double mass = M_PI, v = 0.01;
  const auto   law      = disk_force_law(1., 1., -1.7437);
  double       previous = 1.;
  for (const double tau : {0.02, 0.05, 0.1})
    {
      const auto by_force   = collide(mass, v, law, tau, EndCriterion::force);
      const auto by_overlap = collide(mass, v, law, tau, EndCriterion::overlap);
      CHECK(by_force.epsilon < previous);
      CHECK(by_force.contact_time < by_overlap.contact_time);
      CHECK(by_force.epsilon > by_overlap.epsilon);
      previous = by_force.epsilon;
    }
}
