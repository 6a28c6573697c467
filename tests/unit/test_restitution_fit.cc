#include "reference/dem_contact_models.h"
#include "reference/hertz_first_yield.h"
#include "restitution/restitution_fit.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;

TEST_CASE("Thornton's fit recovers the limiting pressure of its own model",
          "[dem]")
{
  const double yield_strain = 0.002, pressure_ratio = 2.7;
  const double v_y =
    Reference::sphere_yield_velocity(pressure_ratio, yield_strain);
  RestitutionTable table;
  for (const double u : {0.8, 2., 6., 20.})
    {
      table.v.push_back(u * v_y);
      table.epsilon.push_back(Reference::thornton_ning_epsilon(u));
      table.error.push_back(1e-3);
    }
  const ThorntonFit fit = fit_thornton(table, yield_strain);
  CHECK(fit.pressure_ratio == Approx(pressure_ratio).epsilon(1e-6));
  CHECK(fit.yield_speed == Approx(v_y).epsilon(1e-5));
  CHECK(fit.max_residual < 1e-9);
  REQUIRE(fit.epsilon.size() == 4);
  CHECK(fit.epsilon[0] == 1.);
}

TEST_CASE("Luding's fit recovers kp / k1 of its own model", "[dem]")
{
  const double     a = 2., v_p = 5e-4; // v_p at the highest speed
  RestitutionTable table;
  for (const double v : {2e-5, 5e-5, 9e-5, 2e-4, 5e-4})
    {
      table.v.push_back(v);
      table.epsilon.push_back(Reference::luding_epsilon(v / v_p, a));
      table.error.push_back(1e-3);
    }
  const LudingFit fit = fit_luding(table);
  CHECK(fit.stiffness_ratio == Approx(1. + a).epsilon(1e-6));
  CHECK(fit.plastic_speed == Approx(v_p).epsilon(1e-6));
  // a minimum's location is found to about sqrt(machine epsilon)
  CHECK(fit.max_residual < 1e-7);
  REQUIRE(fit.epsilon.size() == 5);
}
