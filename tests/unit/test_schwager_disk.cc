#include "reference/collision_ode.h"
#include "reference/schwager_disk.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace DiskImpact::Reference;

namespace
{
  /// A disk on a rigid wall in physical units, deliberately not unit-valued,
  /// so that the ODE also checks the mapping to the scaled variables.
  struct PhysicalDisk
  {
    double E2       = 2.5;
    double density  = 1.3;
    double radius   = 0.7;
    double constant = -1.7437;

    double
    wave_speed() const
    {
      return std::sqrt(E2 / density);
    }

    /// epsilon of the ODE at scaled velocity v and scaled damping alpha.
    double
    epsilon(const double v, const double alpha, const EndCriterion end) const
    {
      // v = (g / c) e^{-C} / 4 and alpha = A c / R, inverted
      const double g    = 4. * std::exp(constant) * v * wave_speed();
      const double A    = alpha * radius / wave_speed();
      const double mass = density * M_PI * radius * radius;
      REQUIRE(schwager_scaled_velocity(g / wave_speed(), constant) ==
              Approx(v).epsilon(1e-14));
      REQUIRE(schwager_scaled_damping(A, wave_speed(), radius) ==
              Approx(alpha).epsilon(1e-14));
      return collide(mass, g, disk_force_law(E2, radius, constant), A, end)
        .epsilon;
    }
  };

  /// The order p of err(alpha) ~ alpha^p from alpha and 2 alpha.
  double
  observed_order(const double error_at_alpha, const double error_at_2alpha)
  {
    return std::log2(error_at_2alpha / error_at_alpha);
  }

  const double order_tolerance = 0.1;
} // namespace

TEST_CASE("Schwager disk: c_0 and c_1 in closed form", "[schwager]")
{
  const auto c = schwager_c_coefficients(2);
  CHECK(c[0] == Approx(schwager_c0_closed_form()).epsilon(1e-14));
  CHECK(c[1] == Approx(schwager_c1_closed_form()).epsilon(1e-14));
  CHECK(schwager_c1_closed_form() == Approx(-0.15169744).epsilon(1e-8));
}

TEST_CASE("Schwager disk: coefficients", "[schwager]")
{
  const SchwagerDiskRestitution restitution(8);
  const auto                   &c = restitution.c_coefficients();
  const auto                   &d = restitution.d_coefficients();
  REQUIRE(c.size() == 8);
  REQUIRE(d.size() == 8);
  // a_k (-1)^k < 0 for k >= 1: every c_k past c_0 is negative, and |c_k|
  // decreases (the tail bound of the truncation test relies on it)
  for (unsigned int k = 1; k < c.size(); ++k)
    {
      CHECK(c[k] < 0.);
      CHECK(std::abs(c[k]) < std::abs(c[k - 1]));
    }
  // d_0 = -c_0^2 and d_1 = -2 c_0 c_1 = pi^2 (ln 4 - 1) / 16
  CHECK(d[0] == Approx(-M_PI * M_PI / 16.).epsilon(1e-14));
  CHECK(d[1] == Approx(M_PI * M_PI * (std::log(4.) - 1.) / 16.).epsilon(1e-14));
  // the legible entries of the printed Table I
  CHECK(c[2] == Approx(-0.02237433).epsilon(1e-7));
  CHECK(d[2] == Approx(0.250419).epsilon(1e-6));
  CHECK(d[3] == Approx(0.029518).epsilon(1e-5));
}

TEST_CASE("Schwager disk: the series eq. 56 against the un-expanded eq. 41",
          "[schwager]")
{
  const double alpha = 1.;
  // far from v_max the series converges fast: quadrature accuracy
  {
    const SchwagerDiskRestitution restitution(16);
    for (const double v : {1e-4, 1e-2, 0.1})
      CHECK(
        std::abs(restitution.first_order(alpha, v) -
                 SchwagerDiskRestitution::first_order_unexpanded(alpha, v)) <=
        1e-13);
  }
  // The omitted terms -sqrt(8) c_k u^{-k-1/2}, k >= n, are all positive
  // and decrease: their sum lies between the first of them and the
  // geometric bound first / (1 - 1/u).
  for (const unsigned int n : {4u, 8u})
    {
      const SchwagerDiskRestitution restitution(n);
      const double                  c_n = schwager_c_coefficients(n + 1)[n];
      for (const double v : {0.15, 0.2, 0.25})
        {
          const double u     = schwager_series_variable(v);
          const double first = -std::sqrt(8.) * c_n * std::pow(u, -(n + 0.5));
          const double omitted =
            SchwagerDiskRestitution::first_order_unexpanded(alpha, v) -
            restitution.first_order(alpha, v);
          INFO("n = " << n << ", v = " << v << ", omitted " << omitted);
          CHECK(omitted >= first * (1. - 1e-6));
          CHECK(omitted <= first / (1. - 1. / u));
        }
    }
}

TEST_CASE("Schwager disk: f_2 of eqs. 77-79 satisfies the consistency eq. 71",
          "[schwager]")
{
  // f_2 = (f_1^2 + v f_1 f_1') / 2 with f_1' by central differences. The
  // identity holds for the untruncated series: with 16 terms the omitted
  // d_k u^{-k} stay below 1e-9 for u >= 2.4 (v <= 0.2).
  const SchwagerDiskRestitution restitution(16);
  for (const double v : {1e-3, 0.05, 0.15, 0.2})
    {
      const double h        = 1e-5 * v;
      const double f1       = restitution.first_order_term(v);
      const double f1_prime = (restitution.first_order_term(v + h) -
                               restitution.first_order_term(v - h)) /
                              (2. * h);
      const double f2 = restitution.second_order_term(v);
      INFO("v = " << v);
      CHECK(f2 == Approx(0.5 * (f1 * f1 + v * f1 * f1_prime)).epsilon(1e-7));
      // 1 + W = 1 - u < 0 and d_0 < 0: the second-order term is positive
      CHECK(f2 > 0.);
    }
}

TEST_CASE("Schwager disk: the velocity limit of the log law", "[schwager]")
{
  const SchwagerDiskRestitution restitution(8);
  const double                  v_max = schwager_maximum_scaled_velocity();
  CHECK(v_max == Approx(1. / (std::sqrt(2.) * M_E)).epsilon(1e-15));
  CHECK(schwager_series_variable(v_max) == Approx(1.).epsilon(1e-7));
  CHECK(restitution.first_order(0.01, v_max) < 1.);
  CHECK_THROWS_AS(restitution.second_order(0.01, v_max), std::domain_error);
  CHECK_THROWS_AS(restitution.first_order(0.01, 1.001 * v_max),
                  std::domain_error);
  CHECK_THROWS_AS(restitution.first_order(0.01, 0.), std::domain_error);
  CHECK_THROWS_AS(
    SchwagerDiskRestitution::first_order_unexpanded(0.01, 1.001 * v_max),
    std::domain_error);
}

TEST_CASE("Schwager disk: eqs. 56 and 80 against the ODE, overlap criterion",
          "[schwager]")
{
  // The energy balance (eq. 21) and the time reversal (eq. 66) assume the
  // collision ends at zero overlap. Then eq. 56 errs by O(alpha^2) and
  // eq. 80 by O(alpha^3).
  const PhysicalDisk            disk;
  const SchwagerDiskRestitution restitution(16);
  const double                  alphas[] = {0.01, 0.02, 0.04};
  for (const double v : {0.01, 0.1, 0.2})
    {
      double first[3], second[3];
      for (unsigned int i = 0; i < 3; ++i)
        {
          const double ode = disk.epsilon(v, alphas[i], EndCriterion::overlap);
          first[i]         = ode - restitution.first_order(alphas[i], v);
          second[i]        = ode - restitution.second_order(alphas[i], v);
        }
      for (unsigned int i = 0; i < 2; ++i)
        {
          INFO("v = " << v << ", alpha = " << alphas[i] << ", eq. 56 error "
                      << first[i] << " -> " << first[i + 1] << ", eq. 80 error "
                      << second[i] << " -> " << second[i + 1]);
          CHECK(std::abs(observed_order(first[i], first[i + 1]) - 2.) <=
                order_tolerance);
          CHECK(std::abs(observed_order(second[i], second[i + 1]) - 3.) <=
                order_tolerance);
        }
    }
}

TEST_CASE("Schwager disk: the force criterion differs at O(alpha^2)",
          "[schwager]")
{
  // Ending at zero total force (Schwager & Pöschel 2007) raises epsilon by
  // G = alpha^2 (-1 - 2s) / (4 s^2), so eq. 80 alone errs by O(alpha^2)
  // against it, and eq. 80 plus G by O(alpha^3).
  const PhysicalDisk            disk;
  const SchwagerDiskRestitution restitution(16);
  const double                  alphas[] = {0.01, 0.02, 0.04};
  for (const double v : {0.01, 0.1, 0.2})
    {
      // G is evaluated at w = v, where the exact exit speed is
      // w = epsilon v = (1 + alpha f_1) v; G grows like w^{1 + kappa},
      // kappa = d ln[(-1 - 2s) / s^2] / d ln w < 0.5 for s < -3, so the
      // relative deviation is below 1.5 |f_1| alpha.
      const double f1 = restitution.first_order_term(v);
      double       corrected[3];
      for (unsigned int i = 0; i < 3; ++i)
        {
          const double alpha    = alphas[i];
          const double by_force = disk.epsilon(v, alpha, EndCriterion::force);
          const double by_overlap =
            disk.epsilon(v, alpha, EndCriterion::overlap);
          const double difference = by_force - by_overlap;
          INFO("v = " << v << ", alpha = " << alpha << ", difference "
                      << difference);
          CHECK(
            difference ==
            Approx(SchwagerDiskRestitution::end_criterion_difference(alpha, v))
              .epsilon(1.5 * std::abs(f1) * alpha));
          corrected[i] =
            by_force - restitution.second_order_force_criterion(alpha, v);
        }
      for (unsigned int i = 0; i < 2; ++i)
        {
          INFO("v = " << v << ", alpha = " << alphas[i] << ", error "
                      << corrected[i] << " -> " << corrected[i + 1]);
          CHECK(std::abs(observed_order(corrected[i], corrected[i + 1]) - 3.) <=
                order_tolerance);
        }
    }
}
