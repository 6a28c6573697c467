#include "reference/log_contact_law.h"
#include "reference/tangential_compliance.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;

TEST_CASE("Mindlin's sphere: initial stiffness 8 G a / (2 - nu), full slip",
          "[tangential]")
{
  const auto   sphere = Reference::tangential_compliance(true);
  const double nu = 0.3, a = 0.05, load = 1e-4; // load = mu P / (E* R)
  // G = E* (1 - nu) / 2 (E* = 1), so dQ/d delta = 8 G a / (2 - nu) at q -> 0.
  const double q     = 1e-7;
  const double slope = q * load / sphere->displacement(q, load, a, nu);
  CHECK(slope == Approx(8. * 0.5 * (1. - nu) * a / (2. - nu)).epsilon(1e-6));
  // At full slip 3 mu P (2 - nu) / (16 G a), the stick radius zero.
  CHECK(sphere->displacement(1., load, a, nu) ==
        Approx(3. * load * (2. - nu) / (16. * 0.5 * (1. - nu) * a)));
  CHECK(sphere->stick_radius(0.875) == Approx(0.5));
}

TEST_CASE("Cattaneo's disk: the constant C_I of the independent series",
          "[tangential]")
{
  const auto disk = Reference::tangential_compliance(false);
  // bench/disk_tangential_constant.py extrapolates Muskhelishvili's series
  // to C_I = -0.977961 (nu2 = 0.3) and -0.838675 (nu2 = 3/7); the initial
  // slope is (2 ln(4R/a) + C_I - 1) / (pi E2) per unit Q.
  const double a = 0.02, load = 1e-4, q = 1e-7;
  for (const auto &[nu, constant] :
       {std::pair{0.3, -0.977961}, std::pair{3. / 7., -0.838675}})
    {
      const double compliance =
        disk->displacement(q, load, a, nu) / (q * load) * M_PI;
      CHECK(compliance - 2. * std::log(4. / a) + 1. ==
            Approx(constant).margin(2e-6));
    }
  // The stick zone c = a sqrt(1 - q).
  CHECK(disk->stick_radius(0.75) == Approx(0.5));
}

TEST_CASE("The disk's tangential over normal stiffness, from the two laws",
          "[tangential]")
{
  // The slopes of Cattaneo's displacement at q = 0 and of the contact law
  // for the centre of mass, by central differences, at a = 2 sqrt(x).
  const auto disk = Reference::tangential_compliance(false);
  for (const double nu2 : {0.3, 3. / 7.})
    for (const double x : {1e-4, 2.5e-3, 1e-2})
      {
        const double                   a = Reference::hertz_half_width(x);
        const Reference::LogContactLaw normal(
          Reference::centre_of_mass_constant(nu2));
        const double h = 1e-6 * x;
        // delta / R against P / (pi E2 R): k_n = pi E2 / slope.
        const double normal_slope =
          (normal.compression(x + h) - normal.compression(x - h)) / (2. * h);
        // delta_c / R against q for mu P / (E2 R) = 1: k_t = pi E2 / slope,
        // one-sided from q = 0, second order.
        const double dq = 1e-7;
        const double tangential_slope =
          M_PI *
          (4. * disk->displacement(dq, 1., a, nu2) -
           disk->displacement(2. * dq, 1., a, nu2)) /
          (2. * dq);
        CHECK(Reference::disk_tangential_stiffness_ratio(a, nu2) ==
              Approx(normal_slope / tangential_slope).epsilon(1e-6));
      }
}
