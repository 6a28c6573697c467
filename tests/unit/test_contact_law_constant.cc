#include "reference/log_contact_law.h"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace DiskImpact::Reference;

// The contact-law constants of a disk pressed on the wall by a uniform body
// force, evaluated numerically from the elastic field of the derivation in
// docs/theory/disk-contact-constants.md, independently of the closed forms
// coded in log_contact_law.cc. Units R = E2 = P = 1; origin at the contact
// point A, the disk's centre at (1, 0), the far end of the diameter B at
// (2, 0); the body force, of density P / (pi R^2), points to the wall (-x).
namespace
{
  using Vector = std::array<double, 2>;
  using Tensor = std::array<std::array<double, 2>, 2>;

  const double pi    = M_PI;
  const double rho_g = 1. / pi; // body force per area, P / (pi R^2)

  /// Michell's stress field: Flamant's point force P at A (Gerl & Zippelius
  /// 1999, eq. 51), the body-force field (eq. 50 about the centre) and a
  /// uniform biaxial tension P / (2 pi R).
  Tensor
  stress(const double x, const double y)
  {
    const double r = std::hypot(x, y), c = x / r, s = y / r;
    const double s_rr = -2. / pi * c / r;
    const double t    = 1. / (2. * pi);
    const double xi   = x - 1.;
    return {
      {{{s_rr * c * c + t + rho_g / 2. * xi, s_rr * c * s + rho_g / 2. * y}},
       {{s_rr * c * s + rho_g / 2. * y, s_rr * s * s + t - rho_g / 2. * xi}}}};
  }

  /// The part of the displacement that is smooth at A: that of the tension
  /// and of the body-force field.
  Vector
  smooth_displacement(const double x, const double y, const double nu)
  {
    const double xi = x - 1., t = 1. / (2. * pi), c = (1. + nu) * rho_g / 2.;
    return {{(1. - nu) * t * xi + c * (xi * xi + 3. * y * y) / 2.,
             (1. - nu) * t * y - c * xi * y}};
  }

  /// Flamant's displacement of the point force (up to a rigid motion).
  Vector
  flamant_displacement(const double x, const double y, const double nu)
  {
    const double r = std::hypot(x, y), theta = std::atan2(y, x);
    const double s = std::sin(theta), c = std::cos(theta);
    return {{-(2. * std::log(r) + (1. + nu) * s * s) / pi,
             -((1. - nu) * theta - (1. + nu) * s * c) / pi}};
  }

  Vector
  displacement(const double x, const double y, const double nu)
  {
    const Vector f = flamant_displacement(x, y, nu);
    const Vector g = smooth_displacement(x, y, nu);
    return {{f[0] + g[0], f[1] + g[1]}};
  }

  /// The mean of u_x over the disk, in polar coordinates about A
  /// (double-exponential quadrature: u_x ~ ln r at A).
  double
  mean_displacement_x(const double nu)
  {
    boost::math::quadrature::tanh_sinh<double> integrator;
    const auto inner = [&integrator, nu](const double theta) {
      return integrator.integrate(
        [theta, nu](const double r) {
          return r *
                 displacement(r * std::cos(theta), r * std::sin(theta), nu)[0];
        },
        0.,
        2. * std::cos(theta),
        1e-12);
    };
    return integrator.integrate(inner, -pi / 2., pi / 2., 1e-12) / pi;
  }

  /// u_x at the centre of the contact for Hertz's pressure (Gerl & Zippelius
  /// 1999, eq. 46) of half-width a in place of the point force: the
  /// half-plane's surface displacement -(1/pi)[2 ln|y| + 1 + nu] per unit
  /// force, averaged over the pressure, plus the smooth part at A.
  double
  contact_displacement_x(const double a, const double nu)
  {
    const auto weighted = [a, nu](const double t) {
      return 2. / (pi * a * a) * std::sqrt(a * a - t * t) *
             (-(2. * std::log(t) + 1. + nu) / pi);
    };
    boost::math::quadrature::tanh_sinh<double> integrator;
    return 2. * integrator.integrate(weighted, 0., a) +
           smooth_displacement(0., 0., nu)[0];
  }

  /// C of delta = P/(pi E2) [2 ln(4R/a) + C].
  double
  constant_of(const double delta, const double a)
  {
    return pi * delta - 2. * std::log(4. / a);
  }
} // namespace

TEST_CASE("Contact-law constants: the field is Michell's disk on a wall",
          "[reference][contact-law]")
{
  // Traction free on the circle (except at A), in equilibrium with the body
  // force, and the displacement's strain is Hooke's of the stress.
  for (const double phi : {-2.9, -2., -1., -0.3, 0.4, 1.5, 2.5, 3.})
    {
      const Vector n{{std::cos(phi), std::sin(phi)}};
      const Tensor s = stress(1. + n[0], n[1]);
      INFO("phi = " << phi);
      CHECK(std::abs(s[0][0] * n[0] + s[0][1] * n[1]) <= 1e-14);
      CHECK(std::abs(s[1][0] * n[0] + s[1][1] * n[1]) <= 1e-14);
    }
  const double h = 1e-4; // fourth-order central differences
  for (const double nu : {0., 0.33, 0.8})
    for (const Vector p : {Vector{{0.5, 0.2}},
                           Vector{{1.3, -0.4}},
                           Vector{{1.8, 0.1}},
                           Vector{{0.2, 0.05}}})
      {
        const double x = p[0], y = p[1];
        const auto   dx = [&](const auto &f) {
          return (8. * (f(x + h, y) - f(x - h, y)) - f(x + 2. * h, y) +
                  f(x - 2. * h, y)) /
                 (12. * h);
        };
        const auto dy = [&](const auto &f) {
          return (8. * (f(x, y + h) - f(x, y - h)) - f(x, y + 2. * h) +
                  f(x, y - 2. * h)) /
                 (12. * h);
        };
        const auto sxx = [](double a, double b) { return stress(a, b)[0][0]; };
        const auto sxy = [](double a, double b) { return stress(a, b)[0][1]; };
        const auto syy = [](double a, double b) { return stress(a, b)[1][1]; };
        const auto ux  = [nu](double a, double b) {
          return displacement(a, b, nu)[0];
        };
        const auto uy = [nu](double a, double b) {
          return displacement(a, b, nu)[1];
        };
        INFO("nu2 = " << nu << ", point " << x << ", " << y);
        CHECK(std::abs(dx(sxx) + dy(sxy) - rho_g) <= 1e-9);
        CHECK(std::abs(dx(sxy) + dy(syy)) <= 1e-9);
        const Tensor s = stress(x, y);
        CHECK(std::abs(dx(ux) - (s[0][0] - nu * s[1][1])) <= 1e-9);
        CHECK(std::abs(dy(uy) - (s[1][1] - nu * s[0][0])) <= 1e-9);
        CHECK(std::abs(dy(ux) + dx(uy) - 2. * (1. + nu) * s[0][1]) <= 1e-9);
      }
}

TEST_CASE("Contact-law constants: C_com and C_diameter by quadrature",
          "[reference][contact-law]")
{
  // delta_com = u_x(A) - mean u_x and delta_diameter = u_x(A) - u_x(B) for
  // Hertz's contact; C is independent of a as a -> 0 (the field's O(a^2)
  // corrections aside, which the point-force field does not have).
  for (const double nu : {0., 0.25, 0.33, 3. / 7., 9. / 11.})
    {
      const double mean = mean_displacement_x(nu);
      const double u_B  = displacement(2., 0., nu)[0];
      // Here the centre point moves with the centre of mass.
      CHECK(std::abs(displacement(1., 0., nu)[0] - mean) <= 1e-12);
      for (const double a : {1e-2, 1e-4})
        {
          const double u_A = contact_displacement_x(a, nu);
          INFO("nu2 = " << nu << ", a/R = " << a);
          CHECK(std::abs(constant_of(u_A - mean, a) -
                         centre_of_mass_constant(nu)) <= 1e-10);
          CHECK(std::abs(constant_of(u_A - u_B, a) - diameter_constant()) <=
                1e-10);
        }
    }
  // The earlier fit -1 - 2/pi - nu2/4 lies 3.254e-4 below for every nu2.
  for (const double nu : {0., 0.5})
    CHECK(std::abs(-1. - 2. / pi - nu / 4. - centre_of_mass_constant(nu) +
                   3.254e-4) <= 1e-7);
}
