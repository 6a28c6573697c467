// The analytic torsional (m = 0) modes of the free sphere: the roots
// against the traction-free condition in its derivative form, checked with
// Boost's j_n' (not the recurrence the class uses), the n = 1 roots
// against the zeros of j_2, Lamb's classical lowest root, the search for
// missed roots, and the ordering of the labels (their parity: regression
// modal_sphere_torsion).

#include "reference/sphere_torsional_modes.h"

#include <boost/math/special_functions/bessel_prime.hpp>
#include <boost/math/tools/roots.hpp>
#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact::Reference;

namespace
{
  /// sigma_{r phi} / mu at r = R: xi j_n'(xi) - j_n(xi).
  double
  traction(const unsigned int n, const double xi)
  {
    return xi * boost::math::sph_bessel_prime(n, xi) -
           boost::math::sph_bessel(n, xi);
  }
} // namespace

TEST_CASE("torsional roots make the surface traction vanish",
          "[reference][sphere]")
{
  const SphereTorsionalModes modes(1., 1.);
  for (unsigned int n = 1; n <= 8; ++n)
    {
      const auto roots = modes.xi_roots(n, 30.);
      REQUIRE(roots.size() >= 5);
      for (const double xi : roots)
        {
          CAPTURE(n, xi);
          // Bracket the derivative form's root around the computed one.
          boost::uintmax_t iterations = 200;
          const auto       bracket    = boost::math::tools::toms748_solve(
            [n](const double x) { return traction(n, x); },
            xi - 1e-3,
            xi + 1e-3,
            boost::math::tools::eps_tolerance<double>(52),
            iterations);
          CHECK(xi ==
                Approx(0.5 * (bracket.first + bracket.second)).epsilon(1e-13));
        }
      // No root missed: sign changes of the traction on a fine grid.
      unsigned int changes = 0;
      for (double x = 0.5 * n + 1e-3; x + 1e-3 < 30.; x += 1e-3)
        changes += traction(n, x) * traction(n, x + 1e-3) < 0.;
      CHECK(changes == roots.size());
    }
}

TEST_CASE("torsional modes of degree 1 are the zeros of j_2; Lamb's (2, 0)",
          "[reference][sphere]")
{
  // The first zeros of j_2 (those of J_{5/2}, tabulated to ten digits) and
  // the lowest torsional mode, xi = 2.5011 (Lamb 1882).
  const SphereTorsionalModes modes(2., 0.5);
  const double               c_T_over_R = 4.;
  CHECK(modes.omega({1, 0, ModeFamily::torsional}) / c_T_over_R ==
        Approx(5.7634591969).epsilon(1e-10));
  CHECK(modes.omega({1, 1, ModeFamily::torsional}) / c_T_over_R ==
        Approx(9.0950113305).epsilon(1e-10));
  CHECK(modes.omega({1, 2, ModeFamily::torsional}) / c_T_over_R ==
        Approx(12.3229409706).epsilon(1e-10));
  CHECK(modes.omega({2, 0, ModeFamily::torsional}) / c_T_over_R ==
        Approx(2.5011).margin(1e-4));
  CHECK(modes.omega({0, 0, ModeFamily::rigid}) == 0.);
  CHECK_THROWS(modes.omega({2, 0, ModeFamily::spheroidal}));
}

TEST_CASE("lowest torsional modes are ascending", "[reference][sphere]")
{
  const SphereTorsionalModes modes(1., 1.);
  const auto                 labels = modes.lowest_modes(30);
  REQUIRE(labels.size() == 30);
  CHECK(labels[0] == ModeLabel{2, 0, ModeFamily::torsional});
  for (unsigned int i = 1; i < labels.size(); ++i)
    CHECK(modes.omega(labels[i]) > modes.omega(labels[i - 1]));
}
