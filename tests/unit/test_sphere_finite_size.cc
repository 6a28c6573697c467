#include "reference/sphere_finite_size.h"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/digamma.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace DiskImpact::Reference;

// The finite-size constants of the sphere, evaluated independently of the
// closed forms in sphere_finite_size.cc: each Legendre degree m of the
// sphere's response to a point force at the pole is solved here from its
// 2x2 traction system (Lame's solutions grad(rho^m P_m) and
// rho^2 grad(w) + alpha x w, w = rho^m P_m), and the series are summed
// numerically (docs/theory/sphere-finite-size.md).
// Units P = R = E* = 1.
namespace
{
  struct Lame
  {
    double nu, mu, lambda;

    explicit Lame(const double poisson)
        : nu(poisson)
    {
      const double E = 1. - nu * nu; // E* = 1
      mu             = E / (2. * (1. + nu));
      lambda         = E * nu / ((1. + nu) * (1. - 2. * nu));
    }

    /// Surface tractions (sigma_rr, sigma_rtheta) per P_m, dP_m/dtheta at
    /// rho = 1 of u_rho = A rho^k P_m, u_theta = B rho^k dP_m/dtheta.
    std::array<double, 2>
    traction(const int m, const double A, const double B, const int k) const
    {
      return {{lambda * (k * A + 2. * A - m * (m + 1.) * B) + 2. * mu * k * A,
               mu * (A + k * B - B)}};
    }

    /// Navier's equation holds for rho^2 grad(w) + alpha x w.
    double
    alpha(const int m) const
    {
      return -(2. * m + (4. * m + 2.) * (1. - 2. * nu)) / (m + 5. - 4. * nu);
    }

    /// Surface coefficient U_m of u_rho for m >= 2: the traction of the
    /// point force, -(2m + 1)/(4 pi) P_m, and no shear.
    double
    radial_coefficient(const int m) const
    {
      const double a  = alpha(m);
      const auto   t1 = traction(m, m, 1., m - 1);
      const auto   t2 = traction(m, m + a, 1., m + 1);
      const double s  = -(2. * m + 1.) / (4. * M_PI);
      const double d  = t1[0] * t2[1] - t2[0] * t1[1];
      const double c1 = s * t2[1] / d, c2 = -s * t1[1] / d;
      return c1 * m + c2 * (m + a);
    }

    /// U_0: the uniform dilation carrying -P_0 / (4 pi).
    double
    dilation_coefficient() const
    {
      return -1. / (4. * M_PI * (3. * lambda + 2. * mu));
    }

    /// U_1: Lame's m = 1 solution, the body force's particular solution
    /// u = c rho^2 e_z, and the translation that zeroes the mean of u_z.
    double
    first_coefficient() const
    {
      const double a  = alpha(1);
      const double b  = 3. / (4. * M_PI);
      const double cp = -b / (8. * mu + 2. * lambda);
      const auto   t2 = traction(1, 1. + a, 1., 2);
      const auto   tp = traction(1, cp, cp, 2);
      const double c2 = (-3. / (4. * M_PI) - tp[0]) / t2[0];
      REQUIRE(std::abs(c2 * t2[1] + tp[1]) < 1e-14); // equilibrium
      const double translation = -(c2 * (3. + a) + 3. * cp) / 5.;
      return c2 * (1. + a) + cp + translation;
    }
  };

  /// sum_{m >= 1} sign^m r_m, r_m = U_m + 1/pi - D1/m: partial sums to
  /// N, 2N, 4N with Richardson's extrapolation in 1/N (plain sums) or the
  /// mean of two successive partial sums (alternating).
  double
  remainder_sum(const Lame &lame, const double D1, const int sign)
  {
    auto r = [&](const int m) {
      const double U =
        m == 1 ? lame.first_coefficient() : lame.radial_coefficient(m);
      return U + 1. / M_PI - D1 / m;
    };
    auto partial = [&](const int N) {
      double s = 0., factor = 1.;
      for (int m = 1; m <= N; ++m)
        {
          factor *= sign;
          s += factor * r(m);
        }
      return s;
    };
    if (sign < 0)
      return 0.5 * (partial(20000) + partial(20001));
    const double s1 = partial(4000), s2 = partial(8000), s4 = partial(16000);
    const double e1 = 2. * s2 - s1, e2 = 2. * s4 - s2;
    return (4. * e2 - e1) / 3.;
  }
} // namespace

TEST_CASE("Sphere finite size: complex digamma against Boost and identities",
          "[reference][sphere]")
{
  for (const double x : {0.1, 0.5, 1., 2., 7.3, 12., 50.})
    CHECK(std::abs(digamma({x, 0.}) - boost::math::digamma(x)) <
          4e-15 * std::max(1., std::abs(boost::math::digamma(x))));
  // psi(z + 1) = psi(z) + 1/z and psi(conj z) = conj psi(z).
  for (const std::complex<double> z : {std::complex<double>(0.3, 0.8),
                                       std::complex<double>(2.7, -1.9),
                                       std::complex<double>(9.5, 4.)})
    {
      CHECK(std::abs(digamma(z + 1.) - digamma(z) - 1. / z) < 1e-14);
      CHECK(std::abs(digamma(std::conj(z)) - std::conj(digamma(z))) < 1e-15);
    }
  // Im psi(1 + i y) = -1/(2y) + (pi/2) coth(pi y).
  const double y = 1.3;
  CHECK(std::abs(digamma({1., y}).imag() -
                 (-0.5 / y + M_PI / 2. / std::tanh(M_PI * y))) < 1e-14);
  CHECK_THROWS_AS(digamma({-0.5, 1.}), std::invalid_argument);
}

TEST_CASE("Sphere finite size: closed forms against the summed Lame series",
          "[reference][sphere]")
{
  for (const double nu : {-0.5, 0., 0.15, 0.3, 0.45, 0.49})
    {
      CAPTURE(nu);
      const Lame             lame(nu);
      const SphereFiniteSize c  = sphere_finite_size_constants(nu);
      const double           pi = M_PI, ln2 = std::log(2.);

      // The series' 1/m term is the derived logarithm's coefficient D1.
      const double D1 =
        -(1. - 2. * nu) * (1. - 2. * nu) / (2. * pi * (1. - nu));
      CHECK(c.log_coefficient == Approx(D1).margin(1e-15));
      // m (U_m + 1/pi) = D1 + w2/m + w3/m^2 + ...: Richardson's
      // extrapolation from m = 1000, 2000, 4000 (rounding grows with m).
      auto scaled = [&](const int m) {
        return m * (lame.radial_coefficient(m) + 1. / pi);
      };
      const double e1 = 2. * scaled(2000) - scaled(1000);
      const double e2 = 2. * scaled(4000) - scaled(2000);
      CHECK((4. * e2 - e1) / 3. == Approx(D1).margin(1e-7));

      // L: ln(|x - s| / a) averaged over the flat punch's weight at x and
      // Hertz's pressure at s, = int ln t d[F(t) G(t)] (the angle averages
      // ln |x - s| to ln max(|x|, |s|)).
      boost::math::quadrature::tanh_sinh<double> quadrature;
      const double L = quadrature.integrate([](const double t) {
        const double w = std::sqrt((1. - t) * (1. + t));
        if (t <= 0. || w <= 0.) // both ends: the integrand tends to 0
          return 0.;
        const double F = 1. - w, G = 1. - w * w * w;
        return std::log(t) * (t / w * G + F * 3. * t * w);
      });
      CHECK(L == Approx(2. * ln2 - 19. / 12.).margin(1e-12));

      const double v1 = (1. - 2. * nu) / (2. * pi * (1. - nu));
      const double U0 = lame.dilation_coefficient();
      const double C_h =
        -U0 - 1. / pi - D1 * ln2 - remainder_sum(lame, D1, 1) - v1;
      const double far_pole =
        -(U0 + 0.5 / pi - D1 * ln2 + remainder_sum(lame, D1, -1));
      CHECK(c.centre_of_mass == Approx(D1 * L + C_h).margin(1e-9));
      CHECK(c.diameter - c.centre_of_mass == Approx(far_pole).margin(1e-9));
    }
  CHECK_THROWS_AS(sphere_finite_size_constants(0.9), std::invalid_argument);
  CHECK_THROWS_AS(sphere_finite_size_constants(-0.9), std::invalid_argument);
}

TEST_CASE("Sphere finite size: the FE study's constants within their bars",
          "[reference][sphere]")
{
  // postprocess/sphere_contact_study.py with D1 fixed at the derived value
  // (docs/validation/sphere-contact-law.md): D0 of the centre of mass and of
  // the diameter, and their bars (mesh, grading, penalty, fit).
  struct Measured
  {
    double nu, com, diameter, bar;
  };
  for (const Measured &m : {Measured{0., -0.6326, -0.4844, 0.0044},
                            Measured{0.15, -0.6074, -0.4455, 0.0056},
                            Measured{0.3, -0.5488, -0.3656, 0.0067},
                            Measured{0.45, -0.4620, -0.2436, 0.0107}})
    {
      CAPTURE(m.nu);
      const SphereFiniteSize c = sphere_finite_size_constants(m.nu);
      CHECK(std::abs(c.centre_of_mass - m.com) < m.bar);
      CHECK(std::abs(c.diameter - m.diameter) < m.bar);
    }
}
