#include "reference/collision_ode.h"
#include "reference/dem_contact_models.h"
#include "reference/hertz_impact.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact::Reference;

TEST_CASE("LIGGGHTS' Hertz restitution: its epsilon and the input for it",
          "[dem]")
{
  // Tsuji's sqrt(5/6) makes the Hertz model's epsilon nearly its input
  // (the LIGGGHTS run of bench/dem_check.py measures 0.9000017 at 2000
  // steps per contact, 0.9000003 at 4000).
  CHECK(liggghts_hertz_epsilon(0.9) == Approx(0.9).margin(1e-6));
  CHECK(liggghts_hertz_epsilon(1.) == 1.);
  for (const double eps : {0.3, 0.7, 0.95, 0.999})
    CHECK(liggghts_hertz_epsilon(liggghts_hertz_input(eps)) ==
          Approx(eps).margin(1e-12));
  CHECK_THROWS(liggghts_hertz_input(1.5));
}

TEST_CASE("LAMMPS' viscoelastic damping is seed 003's A dF/dt", "[dem]")
{
  // A sphere on a wall, not unit-valued: E*, R, m, A, v.
  const double e_star = 7.3, radius = 0.4, mass = 2.1, A = 0.03, v = 0.2;
  const ForceLaw hertz{
    [&](const double d) {
      return d > 0. ? hertz_sphere_stiffness(e_star, radius) * std::pow(d, 1.5) :
                      0.;
    },
    [&](const double d) {
      return d > 0. ? 1.5 * hertz_sphere_stiffness(e_star, radius) *
                        std::sqrt(d) :
                      0.;
    }};
  const double eta = lammps_viscoelastic_damping(A, e_star, mass);
  // LAMMPS: eta_n0 a m_eff d' with a = sqrt(R_eff d).
  const auto lammps = [&](const double d, const double d_dot) {
    return d > 0. ? eta * std::sqrt(radius * d) * mass * d_dot : 0.;
  };
  const auto seed = collide(mass, v, hertz, A, EndCriterion::force);
  const auto dem  = collide(mass, v, hertz, lammps, EndCriterion::force);
  CHECK(dem.epsilon == Approx(seed.epsilon).epsilon(1e-10));
  CHECK(dem.contact_time == Approx(seed.contact_time).epsilon(1e-10));
  CHECK(seed.epsilon < 0.99);
}
