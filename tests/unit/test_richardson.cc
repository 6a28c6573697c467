#include "dynamics/richardson.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;

TEST_CASE("Richardson: second-order sequence", "[richardson]")
{
  // f(h) = 1 + 0.3 h^2 + 0.1 h^3 at h = 1 ... 1/16: the triples' orders
  // 2.22, 2.12, 2.06 agree within 0.25; the limit within the GCI of the
  // finest value.
  std::vector<double> values;
  for (const double h : {1., 0.5, 0.25, 0.125, 0.0625})
    values.push_back(1. + 0.3 * h * h + 0.1 * h * h * h);
  const auto e = richardson_estimate(values, 2., 2.);
  REQUIRE(e.clean);
  CHECK(e.order == Approx(2.03).margin(0.05));
  CHECK(e.order_scatter < 0.1);
  CHECK(std::abs(e.extrapolated - 1.) < 0.2 * std::abs(values[4] - 1.));
  CHECK(std::abs(values[4] - 1.) <= e.error);
}

TEST_CASE("Richardson: an order seen in one triple only is not clean",
          "[richardson]")
{
  // The first three values of the sequence above: order 2.22, but not
  // verified by three triples; no extrapolation, 3 |d2| / (q - 1).
  std::vector<double> values;
  for (const double h : {1., 0.5, 0.25})
    values.push_back(1. + 0.3 * h * h + 0.1 * h * h * h);
  const auto   e  = richardson_estimate(values, 2., 2.);
  const double d1 = values[1] - values[0], d2 = values[2] - values[1];
  CHECK_FALSE(e.clean);
  CHECK(std::isnan(e.order_scatter));
  CHECK(e.extrapolated == values[2]);
  CHECK(e.error == Approx(3. * std::abs(d2) / (d1 / d2 - 1.)));
  CHECK(std::abs(values[2] - 1.) <= e.error);
}

TEST_CASE("Richardson: scattered orders are not clean", "[richardson]")
{
  // Differences 0.1, 0.025, 0.0125, 0.003125: triple orders 2, 1, 2
  // (mean 1.67, scatter 0.67).
  const std::vector<double> values{1., 1.1, 1.125, 1.1375, 1.140625};
  const auto                e = richardson_estimate(values, 2., 2.);
  CHECK_FALSE(e.clean);
  CHECK(e.order_scatter == Approx(2. / 3.).epsilon(1e-9));
  CHECK(e.extrapolated == values[4]);
  CHECK(e.error == Approx(3. * 0.003125 / 3.).epsilon(1e-9));
}

TEST_CASE("Richardson: first order in 1/k with ratio 4", "[richardson]")
{
  std::vector<double> values;
  for (const double x : {1., 1. / 4, 1. / 16, 1. / 64, 1. / 256})
    values.push_back(2. + 0.5 * x);
  const auto e = richardson_estimate(values, 4., 1.);
  REQUIRE(e.clean);
  CHECK(e.order == Approx(1.).epsilon(1e-9));
  CHECK(e.extrapolated == Approx(2.).epsilon(1e-12));
}

TEST_CASE("Richardson: oscillating sequence is not extrapolated",
          "[richardson]")
{
  const std::vector<double> values{1.0, 1.2, 1.1};
  const auto                e = richardson_estimate(values, 2., 2.);
  CHECK_FALSE(e.clean);
  CHECK(e.extrapolated == 1.1);
  // 3 max(|d1|, |d2|) / (2^2 - 1)
  CHECK(e.error == Approx(0.2).epsilon(1e-12));
}

TEST_CASE("Richardson: order far from the expected one is not trusted",
          "[richardson]")
{
  // differences 1e-1, 1e-4: observed order ~10 against 2 expected; the last
  // difference with the expected order and safety factor 3
  const std::vector<double> fast{1.0, 1.1, 1.1001};
  const auto                e = richardson_estimate(fast, 2., 2.);
  CHECK_FALSE(e.clean);
  CHECK(e.extrapolated == 1.1001);
  CHECK(e.error == Approx(1e-4).epsilon(1e-9));
  // differences 0.1, 0.09: observed order 0.15 against 2; the slow rate
  // gives a large bar, 3 * 0.09 / (0.1 / 0.09 - 1) = 2.43
  const std::vector<double> slow{1.0, 1.1, 1.19};
  const auto                f = richardson_estimate(slow, 2., 2.);
  CHECK_FALSE(f.clean);
  CHECK(f.error == Approx(2.43).epsilon(1e-9));
}

TEST_CASE("linear extrapolation: exact on a line, the error bar sees a bend",
          "[extrapolation]")
{
  // y = 0.95 - 0.3 x exactly: limit and slope exact, no residual, no error
  const std::vector<double> x{0.1, 0.05, 0.025};
  const auto line = extrapolate_linearly(x, {0.92, 0.935, 0.9425});
  CHECK(line.limit == Approx(0.95).epsilon(1e-14));
  CHECK(line.slope == Approx(-0.3).epsilon(1e-12));
  CHECK(line.residual < 1e-14);
  CHECK(line.error < 1e-14);
  // y = 0.95 - 0.3 x + 2 x^2: the limit moves when the coarsest point is
  // dropped; the error bar covers the true limit 0.95
  std::vector<double> y;
  for (const double xi : x)
    y.push_back(0.95 - 0.3 * xi + 2. * xi * xi);
  const auto bent = extrapolate_linearly(x, y);
  CHECK(bent.residual > 0.);
  CHECK(std::abs(bent.limit - 0.95) <= bent.error);
}

TEST_CASE("Richardson: the run says why a sequence is not clean",
          "[richardson]")
{
  auto because = [](const std::vector<double> &values) {
    return richardson_estimate(values, 2., 2.).not_clean_because;
  };
  using Catch::Matchers::Contains;
  // Five values of f(h) = 1 + 0.3 h^2 + 0.1 h^3: clean, no reason.
  std::vector<double> smooth;
  for (const double h : {1., 0.5, 0.25, 0.125, 0.0625})
    smooth.push_back(1. + 0.3 * h * h + 0.1 * h * h * h);
  CHECK(because(smooth).empty());
  // Its first three: too few levels to verify the order.
  CHECK_THAT(because({smooth[0], smooth[1], smooth[2]}),
             Contains("3 levels; a verified order needs 5"));
  CHECK_THAT(because({1., 1.2}), Contains("2 levels"));
  // The last differences +0.2, -0.1: a sign change, with both differences.
  CHECK_THAT(because({1.0, 1.2, 1.1}),
             Contains("change sign (2.00e-01, -1.00e-01)"));
  // Differences -4.9e-6, -1.69e-4 (the shipped study's three levels): the
  // last one grows.
  CHECK_THAT(because({0.94722248, 0.94721755, 0.94704867}),
             Contains("is not smaller than the one before"));
  // Five values whose first triple oscillates: the last triple alone is
  // monotone, the scatter undefined.
  CHECK_THAT(because({1.0, 0.9, 1.1, 1.15, 1.1625}),
             Contains("an earlier triple"));
  // Triple orders 2, 1, 2: the scatter 0.67 is named.
  CHECK_THAT(because({1., 1.1, 1.125, 1.1375, 1.140625}),
             Contains("scatter by 0.67 > 0.25"));
  // Orders 5, 5, 5 against the expected 2: the order is named.
  std::vector<double> fast;
  for (const double h : {1., 0.5, 0.25, 0.125, 0.0625})
    fast.push_back(1. + std::pow(h, 5.));
  CHECK_THAT(because(fast), Contains("observed order 5.00 is not within"));
}
