// The analytic axisymmetric spheroidal modes of the free sphere (Lamb):
// the breathing modes against their classical closed form, the lowest
// modes against Lamb's tabulated values, and the ordering of the labels.

#include "reference/free_sphere_modes.h"

#include <boost/math/tools/roots.hpp>
#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact::Reference;

TEST_CASE("sphere breathing modes solve xi cot xi = 1 - (xi c_L / 2 c_T)^2",
          "[reference][sphere]")
{
  // Independent reference: the textbook form of the n = 0 condition
  // sigma_rr = 0 for u_r = j_0'(xi r), solved here with its own bracket.
  for (const double nu : {-0.5, 0., 0.25, 0.3, 0.45})
    {
      const FreeSphereModes modes(nu, 1., 1.);
      const double          ratio2      = std::pow(modes.wave_speed_ratio(), 2);
      const auto            closed_form = [&](const double x) {
        return x * std::cos(x) - (1. - 0.25 * ratio2 * x * x) * std::sin(x);
      };
      for (unsigned int l = 0; l < 4; ++l)
        {
          CAPTURE(nu, l);
          const double kappa = modes.kappa({0, l, ModeFamily::radial});
          // Bracket the closed form's root around the computed one.
          boost::uintmax_t iterations = 200;
          const auto       bracket    = boost::math::tools::toms748_solve(
            closed_form,
            kappa - 1e-3,
            kappa + 1e-3,
            boost::math::tools::eps_tolerance<double>(52),
            iterations);
          CHECK(kappa ==
                Approx(0.5 * (bracket.first + bracket.second)).epsilon(1e-13));
        }
    }
}

TEST_CASE("sphere modes match Lamb's values for nu = 1/4",
          "[reference][sphere]")
{
  // Lamb (1882), as tabulated e.g. by Sato & Usami (1962): for Poisson's
  // ratio 1/4 the breathing mode has h R = 0.8160 pi, the lowest modes of
  // degree 1 and 2 have k R = 3.4245 and 2.6399 (k = omega / c_T); four
  // digits, hence the tolerance.
  const FreeSphereModes modes(0.25, 1., 1.);
  const double          ratio = modes.wave_speed_ratio();
  CHECK(modes.kappa({0, 0, ModeFamily::radial}) / M_PI ==
        Approx(0.8160).margin(1e-4));
  CHECK(modes.kappa({1, 0, ModeFamily::spheroidal}) * ratio ==
        Approx(3.4245).margin(1e-4));
  CHECK(modes.kappa({2, 0, ModeFamily::spheroidal}) * ratio ==
        Approx(2.6399).margin(1e-4));
}

TEST_CASE("lowest sphere modes are ascending, each degree once",
          "[reference][sphere]")
{
  const FreeSphereModes modes(0.3, 2., 1.5);
  const auto            lowest = modes.lowest_modes(20, true);
  REQUIRE(lowest.size() == 20);
  // The quadrupole mode (2, 0) is the lowest, as for every nu > 0.
  CHECK(lowest.front() == ModeLabel{2, 0, ModeFamily::spheroidal});
  for (unsigned int i = 0; i < lowest.size(); ++i)
    {
      CAPTURE(i);
      CHECK(lowest[i].family == FreeSphereModes::family(lowest[i].n));
      // A root: the frequency equation changes sign across it.
      const double kappa = modes.kappa(lowest[i]);
      CHECK(modes.frequency_equation(lowest[i].n, kappa * (1. - 1e-12)) *
              modes.frequency_equation(lowest[i].n, kappa * (1. + 1e-12)) <=
            0.);
      if (i > 0)
        CHECK(modes.omega(lowest[i]) > modes.omega(lowest[i - 1]));
      // omega = kappa c_L / R
      CHECK(modes.omega(lowest[i]) ==
            Approx(modes.kappa(lowest[i]) * 2. / 1.5).epsilon(1e-15));
    }
}
