// Rigid-body impulse theory of an oblique impact with Coulomb friction: the
// gross-sliding and sticking regimes against their closed forms and the
// balances they must keep.

#include "reference/rigid_oblique_impact.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace DiskImpact::Reference;

namespace
{
  constexpr double m = 2., R = 0.5;

  ObliqueVelocities
  incoming(const double angle, const double spin = 0.)
  {
    return {std::cos(angle), std::sin(angle), spin};
  }

  double
  kinetic_energy(const ObliqueVelocities &v, const double k)
  {
    return 0.5 * m * (v.normal * v.normal + v.tangential * v.tangential) +
           0.5 * k * m * R * R * v.spin * v.spin;
  }
} // namespace

TEST_CASE("without friction only the normal velocity changes", "[reference]")
{
  const auto impact = rigid_oblique_impact(m, R, 0.4, 0., 0.8, incoming(0.7, 3.));
  CHECK(impact.after.normal == Approx(0.8 * std::cos(0.7)));
  CHECK(impact.after.tangential == std::sin(0.7));
  CHECK(impact.after.spin == 3.);
  CHECK(impact.friction_work == 0.);
  CHECK_FALSE(impact.sticks);
}

TEST_CASE("gross sliding: the tangential restitution of the centre",
          "[reference]")
{
  // Sphere and disk, e_n = 0.9, mu = 0.1: the point slides throughout
  // above tan(theta) = mu (1 + e_n)(1 + 1/k) = 0.665 (sphere), 0.57 (disk).
  for (const double k : {0.4, 0.5})
    for (const double angle : {0.7, 1.0, 1.4})
      {
        const double mu = 0.1, e_n = 0.9;
        REQUIRE(std::tan(angle) > mu * (1. + e_n) * (1. + 1. / k));
        const auto impact =
          rigid_oblique_impact(m, R, k, mu, e_n, incoming(angle));
        CHECK_FALSE(impact.sticks);
        CHECK(impact.after.tangential / std::sin(angle) ==
              Approx(1. - mu * (1. + e_n) / std::tan(angle)).epsilon(1e-14));
        // the spin from the friction impulse mu J_n at the lever arm R
        CHECK(impact.after.spin ==
              Approx(-mu * (1. + e_n) * std::cos(angle) / (k * R))
                .epsilon(1e-14));
      }
}

TEST_CASE("a slow slip stops: the contact point rolls off", "[reference]")
{
  // Backspin that nearly cancels the slip: s = sin(0.3) - R 0.5.
  const double k = 0.4, mu = 0.5, e_n = 0.6;
  const auto   before = incoming(0.3, -0.5);
  const auto   impact = rigid_oblique_impact(m, R, k, mu, e_n, before);
  CHECK(impact.sticks);
  CHECK(impact.slip_after == Approx(0.).margin(1e-15));
  CHECK(std::abs(impact.tangential_impulse) <
        mu * impact.normal_impulse);
  // The regimes meet: at the threshold friction the two impulses agree.
  const double threshold =
    std::abs(impact.slip_before) /
    ((1. + e_n) * before.normal * (1. + 1. / k));
  const auto sliding =
    rigid_oblique_impact(m, R, k, threshold * (1. - 1e-9), e_n, before);
  CHECK_FALSE(sliding.sticks);
  CHECK(sliding.tangential_impulse ==
        Approx(impact.tangential_impulse).epsilon(1e-8));
}

TEST_CASE("angular momentum about the contact point and energy balance",
          "[reference]")
{
  for (const double k : {0.4, 0.5})
    for (const double mu : {0.05, 0.3, 2.})
      for (const double spin : {-2., 0., 1.5})
        {
          const double e_n    = 0.85;
          const auto   before = incoming(0.9, spin);
          const auto   impact = rigid_oblique_impact(m, R, k, mu, e_n, before);
          const auto   moment = [k](const ObliqueVelocities &v) {
            return k * m * R * R * v.spin - m * R * v.tangential;
          };
          CHECK(moment(impact.after) ==
                Approx(moment(before)).epsilon(1e-13));
          // kinetic energy lost = normal loss + friction work
          const double normal_loss =
            0.5 * m * (1. - e_n * e_n) * before.normal * before.normal;
          CHECK(kinetic_energy(before, k) - kinetic_energy(impact.after, k) ==
                Approx(normal_loss + impact.friction_work).epsilon(1e-12));
        }
}

TEST_CASE("bad input to the rigid oblique impact is refused", "[reference]")
{
  CHECK_THROWS_AS(rigid_oblique_impact(m, R, 0.4, -0.1, 0.9, incoming(0.5)),
                  std::invalid_argument);
  CHECK_THROWS_AS(rigid_oblique_impact(m, R, 0.4, 0.1, 1.2, incoming(0.5)),
                  std::invalid_argument);
  CHECK_THROWS_AS(rigid_oblique_impact(m, R, 0.4, 0.1, 0.9, {-1., 0., 0.}),
                  std::invalid_argument);
}
