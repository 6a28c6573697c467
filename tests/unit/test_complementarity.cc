#include "contact/complementarity.h"

#include <catch2/catch.hpp>

#include <random>

using namespace DiskImpact;
using namespace dealii;

namespace
{
  /// A random symmetric positive definite n x n matrix B B^T + n I / 10.
  FullMatrix<double>
  random_spd(const unsigned int n, std::mt19937 &generator)
  {
    std::uniform_real_distribution<double> entry(-1., 1.);
    FullMatrix<double>                     B(n, n), W(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        B(i, j) = entry(generator);
    B.mTmult(W, B);
    for (unsigned int i = 0; i < n; ++i)
      W(i, i) += 0.1 * n;
    return W;
  }
} // namespace

TEST_CASE("Complementarity: a two-point problem solved by hand",
          "[complementarity]")
{
  // W = [2 1; 1 2], q = (-1, 1): with mu2 = 0, g1 = 0 needs mu1 = 1/2, and
  // then g2 = 1 + 1/2 > 0; no other support satisfies the conditions.
  FullMatrix<double> W(2, 2);
  W(0, 0) = W(1, 1) = 2.;
  W(0, 1) = W(1, 0) = 1.;
  Vector<double> q(2);
  q[0]                = -1.;
  q[1]                = 1.;
  const auto solution = solve_complementarity(W, q, 1e-14);
  REQUIRE(solution.converged);
  CHECK(solution.force[0] == Approx(0.5).epsilon(1e-14));
  CHECK(solution.force[1] == 0.);
  CHECK(solution.gap[0] == Approx(0.).margin(1e-14));
  CHECK(solution.gap[1] == Approx(1.5).epsilon(1e-14));
}

TEST_CASE("Complementarity: random problems meet the conditions, warm or cold",
          "[complementarity]")
{
  // mu >= 0, g = q + W mu >= -tol, mu_i g_i = 0: the conditions that make
  // mu the unique minimizer of 1/2 mu^T W mu + q^T mu over mu >= 0.
  std::mt19937                           generator(7);
  std::uniform_real_distribution<double> entry(-1., 1.);
  for (unsigned int trial = 0; trial < 50; ++trial)
    {
      const unsigned int n = 1 + trial % 30;
      const auto         W = random_spd(n, generator);
      Vector<double>     q(n);
      for (auto &value : q)
        value = entry(generator);
      const double tolerance = 1e-12;
      const auto   cold      = solve_complementarity(W, q, tolerance);
      REQUIRE(cold.converged);
      std::vector<bool> support(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          CHECK(cold.force[i] >= 0.);
          CHECK(cold.gap[i] >= -tolerance);
          CHECK(std::abs(cold.force[i] * cold.gap[i]) < 1e-10);
          support[i] = cold.force[i] > 0.;
        }
      // Started from its own support, one solve gives the same forces.
      const auto warm = solve_complementarity(W, q, tolerance, support);
      REQUIRE(warm.converged);
      CHECK(warm.iterations <= 1);
      for (unsigned int i = 0; i < n; ++i)
        CHECK(warm.force[i] == Approx(cold.force[i]).margin(1e-12));
    }
}

TEST_CASE("Complementarity: the mean along a segment, piece by piece",
          "[complementarity]")
{
  // One point: mu(s) = max(0, -q(s) / w) with q from 1 to -1, w = 2:
  // mu = s - 1/2 beyond s = 1/2, mean 1/8.
  FullMatrix<double> w(1, 1);
  w(0, 0) = 2.;
  Vector<double> q0(1), q1(1);
  q0[0] = 1.;
  q1[0] = -1.;
  CHECK(mean_along_segment(w, q0, q1, 1e-14)[0] ==
        Approx(0.125).epsilon(1e-14));

  // Random problems: against the midpoint rule on 20000 subintervals of
  // the pointwise solutions (error below 1e-8 for a piecewise linear mu
  // with a few kinks).
  std::mt19937                           generator(11);
  std::uniform_real_distribution<double> entry(-1., 1.);
  for (unsigned int trial = 0; trial < 5; ++trial)
    {
      const unsigned int n = 3 + trial;
      const auto         W = random_spd(n, generator);
      Vector<double>     a(n), b(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          a[i] = entry(generator);
          b[i] = entry(generator);
        }
      const auto         mean = mean_along_segment(W, a, b, 1e-14);
      Vector<double>     sampled(n);
      const unsigned int samples = 20000;
      for (unsigned int k = 0; k < samples; ++k)
        {
          const double   s = (k + 0.5) / samples;
          Vector<double> q(a);
          q.sadd(1. - s, s, b);
          sampled.add(1. / samples, solve_complementarity(W, q, 1e-14).force);
        }
      for (unsigned int i = 0; i < n; ++i)
        CHECK(mean[i] == Approx(sampled[i]).margin(1e-8));
    }
}
