#include "reference/hertz_first_yield.h"
#include "reference/hertz_impact.h"
#include "reference/log_contact_law.h"
#include "reference/one_dof_impact.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact::Reference;

namespace
{
  /// sqrt(1 - t^2) dt over the contact as cos^2(phi) dphi: smooth.
  template <typename Function>
  double
  over_pressure(const Function &f, const double from, const double to)
  {
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [&](const double phi) {
        return f(std::sin(phi)) * std::cos(phi) * std::cos(phi);
      },
      from,
      to,
      15,
      1e-13);
  }

  /// The sphere's axis stresses over p0 by superposing Boussinesq's point
  /// loads (Johnson 1985, eq. 3.19) over the ring of radius t (a = 1): on
  /// the axis sigma_rr is the mean of the point load's sigma_r and
  /// sigma_theta over the ring.
  double
  boussinesq_axis_von_mises(const double z, const double nu)
  {
    const auto ring = [&](const double t, const bool vertical) {
      const double rho2 = t * t + z * z, rho = std::sqrt(rho2);
      const double rho5 = rho2 * rho2 * rho;
      const double load = 2. * M_PI * t; // per unit pressure and dt
      if (vertical)
        return -load * 3. / (2. * M_PI) * z * z * z / rho5;
      return load / (4. * M_PI) *
             ((1. - 2. * nu) * z / (rho2 * rho) - 3. * z * t * t / rho5);
    };
    const double zz =
      over_pressure([&](const double t) { return ring(t, true); }, 0., M_PI_2);
    const double rr =
      over_pressure([&](const double t) { return ring(t, false); }, 0., M_PI_2);
    return std::abs(rr - zz);
  }

  /// The half-plane's von Mises stress over p0 in plane strain by
  /// superposing Flamant's line loads (Johnson 1985, eq. 2.15) (a = 1).
  double
  flamant_von_mises(const double x, const double z, const double nu)
  {
    const auto component = [&](const double xi, const int which) {
      const double dx = x - xi, rho2 = dx * dx + z * z;
      const double f = -2. / M_PI / (rho2 * rho2);
      return which == 0 ? f * dx * dx * z :
             which == 1 ? f * z * z * z :
                          f * dx * z * z;
    };
    double s[3];
    for (int k = 0; k < 3; ++k)
      s[k] = over_pressure([&](const double t) { return component(t, k); },
                           -M_PI_2,
                           M_PI_2);
    const double yy = nu * (s[0] + s[1]);
    return std::sqrt(0.5 *
                       ((s[0] - yy) * (s[0] - yy) + (yy - s[1]) * (yy - s[1]) +
                        (s[1] - s[0]) * (s[1] - s[0])) +
                     3. * s[2] * s[2]);
  }
} // namespace

TEST_CASE("Hertz's sphere: the axis stresses against Boussinesq's loads",
          "[plasticity][reference]")
{
  for (const double nu : {0.2, 0.3, 0.45})
    for (const double z : {0.1, 0.3, 0.48, 0.8, 1.5, 3.})
      CHECK(sphere_axis_von_mises(z, nu) ==
            Approx(boussinesq_axis_von_mises(z, nu)).epsilon(1e-9));
}

TEST_CASE("Hertz's 2D contact: McEwen's field against Flamant's loads",
          "[plasticity][reference]")
{
  for (const double nu : {0., 0.3, 0.45}) // 0: plane stress
    for (const double x : {0., 0.4, -0.9, 1.3})
      for (const double z : {0.2, 0.7, 1.6})
        CHECK(half_plane_von_mises(x, z, nu) ==
              Approx(flamant_von_mises(x, z, nu)).epsilon(1e-9));
}

TEST_CASE("First yield of Hertz contacts: p0/Y and its depth",
          "[plasticity][reference]")
{
  // Johnson (1985), sections 3.4, 4.2 and 6.2, to the digits printed: the
  // sphere's largest shear stress is 0.31 p0 at z = 0.48 a (von Mises
  // 0.62 p0, p0 = 1.61 Y), the cylinder in plane strain yields at
  // p0 = 1.79 Y at z = 0.70 a (nu = 0.3), both on the axis.
  const auto sphere = sphere_first_yield(0.3);
  CHECK(sphere.pressure_ratio == Approx(1. / 0.62).epsilon(1e-2));
  CHECK(sphere.depth == Approx(0.48).margin(0.01));
  const auto plane = half_plane_first_yield(0.3);
  CHECK(plane.pressure_ratio == Approx(1.79).epsilon(5e-3));
  CHECK(plane.depth == Approx(0.70).margin(0.01));
  // The half-plane's largest von Mises stress is on the axis, in plane
  // strain and in plane stress: nothing off it on a grid over |x| <= 2a,
  // 0 < z <= 2a exceeds it.
  for (const double ratio : {0.3, 0.})
    {
      double largest = 0.;
      for (int i = -40; i <= 40; ++i)
        for (int j = 1; j <= 40; ++j)
          largest =
            std::max(largest, half_plane_von_mises(0.05 * i, 0.05 * j, ratio));
      CHECK(largest <=
            1. / half_plane_first_yield(ratio).pressure_ratio * (1. + 1e-12));
    }
}

TEST_CASE("Speed of first yield: the Hertz impact's peak pressure",
          "[plasticity][reference]")
{
  const double ratio = sphere_first_yield(0.3).pressure_ratio;
  SECTION("sphere on a rigid wall (E* = rho = R = 1)")
  {
    const double yield_strain = 4e-3;
    const double v_y          = sphere_yield_velocity(ratio, yield_strain);
    const auto   impact =
      hertz_sphere_impact(4. / 3. * M_PI, 1., 1., v_y); // m, E*, R, v
    // p0 = (2 E* / pi) sqrt(delta / R).
    CHECK(2. / M_PI * std::sqrt(impact.max_overlap) ==
          Approx(ratio * yield_strain).epsilon(1e-10));
    // Johnson's eq. 11.24: rho v_y^2 / Y = 26 (Y / E*)^4 at p0 = 1.6 Y.
    CHECK(std::pow(sphere_yield_velocity(1.6, yield_strain), 2) /
            yield_strain ==
          Approx(26. * std::pow(yield_strain, 4)).epsilon(0.02));
  }
  SECTION("disk on a rigid wall, the 1-DOF log law (E2 = rho = R = 1)")
  {
    const double ratio_2d     = half_plane_first_yield(0.3).pressure_ratio;
    const double yield_strain = 4e-3;
    const double C            = centre_of_mass_constant(3. / 7.);
    const double v_y          = disk_yield_velocity(ratio_2d, yield_strain, C);
    const auto   impact       = one_dof_impact(v_y, M_PI, 1., 1., C);
    // p0 = sqrt(P E2 / (pi R)).
    CHECK(std::sqrt(impact.max_force / M_PI) ==
          Approx(ratio_2d * yield_strain).epsilon(1e-8));
  }
}
