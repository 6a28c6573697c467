// The analytic free-disk modes: root finder, frequency equations, and the
// printed equations of Gerl & Zippelius 1999 against the determinant built
// here.

#include "reference/free_disk_modes.h"

#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/bessel_prime.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace DiskImpact::Reference;

namespace
{
  /// nu2 = 0.33 (plane stress, Gerl & Zippelius' Fig. 3), c_L = 1, R = 1.
  FreeDiskModes
  paper_disk(const double nu2 = 0.33)
  {
    return FreeDiskModes(nu2, 1., 1.);
  }
} // namespace

TEST_CASE("torsional roots are the zeros of J_2(kappa')", "[reference]")
{
  // Independent reference: Boost's zeros of J_2; kappa' = kappa c_L / c_T.
  for (const double nu2 : {-0.5, 0., 0.33, 0.9})
    {
      const FreeDiskModes modes = paper_disk(nu2);
      for (unsigned int l = 0; l < 5; ++l)
        {
          CAPTURE(nu2, l);
          const double kappa_prime =
            modes.kappa({0, l, ModeFamily::torsional}) *
            modes.wave_speed_ratio();
          CHECK(
            kappa_prime ==
            Approx(boost::math::cyl_bessel_j_zero(2.0, l + 1)).epsilon(1e-13));
        }
    }
}

TEST_CASE("radial roots satisfy the traction-free condition", "[reference]")
{
  // sigma_rr(1) = 0 for u_r = J_1(kappa r): kappa J_1'(kappa) + nu2 J_1 = 0,
  // checked here with Boost's Bessel derivative, independent of the code's.
  const FreeDiskModes modes = paper_disk();
  for (unsigned int l = 0; l < 6; ++l)
    {
      const double k = modes.kappa({0, l, ModeFamily::radial});
      CAPTURE(l, k);
      const double residual = k * boost::math::cyl_bessel_j_prime(1., k) +
                              0.33 * boost::math::cyl_bessel_j(1., k);
      CHECK(std::abs(residual) < 1e-13);
      // and the printed eq. 20 is right
      CHECK(std::abs(modes.printed_eq20(k)) < 1e-13);
    }
}

TEST_CASE("printed eq. 21 (torsional, with nu) is misprinted", "[reference]")
{
  // The printed torsional condition dJ_1/dR - (nu/R) J_1 = 0 is not
  // sigma_rphi = 0; its roots differ from those of J_2(kappa') = 0 for
  // nu2 != 1 (docs/theory/misprints.md).
  const FreeDiskModes modes = paper_disk();
  const double        kp =
    modes.kappa({0, 0, ModeFamily::torsional}) * modes.wave_speed_ratio();
  CHECK(std::abs(modes.printed_eq21(kp)) > 1e-2);
}

TEST_CASE("printed eq. 25 has the roots of the boundary determinant",
          "[reference]")
{
  // For n >= 1, and for n = 0 where it must factor into the radial and
  // torsional families.
  for (const double nu2 : {0.0, 0.33, 0.9})
    {
      const FreeDiskModes modes = paper_disk(nu2);
      for (unsigned int n = 0; n <= 8; ++n)
        {
          std::vector<double> roots;
          if (n == 0)
            {
              roots        = modes.kappa_roots(0, ModeFamily::radial, 12.);
              const auto t = modes.kappa_roots(0, ModeFamily::torsional, 12.);
              roots.insert(roots.end(), t.begin(), t.end());
            }
          else
            roots = modes.kappa_roots(n, ModeFamily::mixed, 12.);
          REQUIRE(!roots.empty());
          for (const double k : roots)
            {
              CAPTURE(nu2, n, k);
              // Sign change of eq. 25 in a +-1e-9 bracket around the root.
              CHECK(modes.printed_eq25(n, k - 1e-9) *
                      modes.printed_eq25(n, k + 1e-9) <=
                    0.);
            }
        }
    }
}

TEST_CASE("root finder misses no root", "[reference]")
{
  // A ten times finer sign-change scan finds the same number of roots.
  const FreeDiskModes modes = paper_disk(0.9);
  for (unsigned int n = 1; n <= 6; ++n)
    {
      const auto   roots = modes.kappa_roots(n, ModeFamily::mixed, 10.);
      unsigned int count = 0;
      const double step  = 1e-4;
      double       f0    = modes.boundary_determinant(n, step);
      for (double k = 2 * step; k <= 10.; k += step)
        {
          const double f1 = modes.boundary_determinant(n, k);
          count += (f0 * f1 < 0.);
          f0 = f1;
        }
      CAPTURE(n);
      CHECK(roots.size() == count);
      for (const double k : roots)
        CHECK(std::abs(modes.boundary_determinant(n, k)) <
              1e-10 * (1 + k * k * k * k));
    }
}

TEST_CASE("lowest modes: ordering and multiplicity", "[reference]")
{
  const FreeDiskModes modes = paper_disk();
  const auto          full  = modes.lowest_modes(40, false);
  const auto          half  = modes.lowest_modes(20, true);
  REQUIRE(full.size() == 40);
  // The lowest mode is the quadrupole (2,0) (Gerl & Zippelius 1999,
  // section 2.2).
  CHECK(full[0] == ModeLabel{2, 0, ModeFamily::mixed});
  CHECK(full[1] == ModeLabel{2, 0, ModeFamily::mixed});
  for (unsigned int i = 1; i < full.size(); ++i)
    CHECK(modes.omega(full[i - 1]) <= modes.omega(full[i]));
  // Each n >= 1 label twice on the full disk, once on the half disk, which
  // has no torsional modes.
  // (the last label may lack its partner, cut off at 40)
  for (unsigned int i = 0; i + 1 < full.size(); ++i)
    if (full[i].n >= 1 && !(full[i] == full.back()))
      CHECK(std::count(full.begin(), full.end(), full[i]) == 2);
  for (const auto &label : half)
    {
      CHECK(std::count(half.begin(), half.end(), label) == 1);
      CHECK(label.family != ModeFamily::torsional);
    }
}

TEST_CASE("omega scales as kappa c_L / R", "[reference]")
{
  const FreeDiskModes unit(0.33, 1., 1.), scaled(0.33, 3., 2.);
  const ModeLabel     mode{2, 1, ModeFamily::mixed};
  CHECK(scaled.omega(mode) == Approx(unit.omega(mode) * 3. / 2.));
}
