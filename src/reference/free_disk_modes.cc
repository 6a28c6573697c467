#include "reference/free_disk_modes.h"

#include "reference/root_scan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    namespace
    {
      double
      bessel_j(const int n, const double x)
      {
        // J_{-n} = (-1)^n J_n
        if (n < 0)
          return ((-n) % 2 == 0 ? 1. : -1.) * std::cyl_bessel_j(-n, x);
        return std::cyl_bessel_j(n, x);
      }

      /// J_n'(x) = (J_{n-1}(x) - J_{n+1}(x)) / 2
      double
      bessel_j_derivative(const int n, const double x)
      {
        return 0.5 * (bessel_j(n - 1, x) - bessel_j(n + 1, x));
      }

      /// J_n''(x) from Bessel's equation, x > 0.
      double
      bessel_j_second_derivative(const int n, const double x)
      {
        return -bessel_j_derivative(n, x) / x -
               (1. - double(n) * n / (x * x)) * bessel_j(n, x);
      }
    } // namespace

    FreeDiskModes::FreeDiskModes(const double in_plane_poisson_ratio,
                                 const double longitudinal_wave_speed,
                                 const double radius)
        : nu2(in_plane_poisson_ratio)
        , c_L(longitudinal_wave_speed)
        , R(radius)
    {
      if (!(nu2 > -1. && nu2 < 1.) || !(c_L > 0.) || !(R > 0.))
        throw std::invalid_argument(
          "FreeDiskModes: need -1 < nu2 < 1, c_L > 0, R > 0");
    }

    double
    FreeDiskModes::wave_speed_ratio() const
    {
      return std::sqrt(2. / (1. - nu2));
    }

    double
    FreeDiskModes::boundary_determinant(const unsigned int n_,
                                        const double       kappa) const
    {
      // Radial profiles on the unit disk: u_r = f(r) cos(n phi),
      // u_phi = g(r) sin(n phi), each linear in the amplitudes (A, B) of
      // Gerl & Zippelius 1999, eq. 19. Evaluated at r = 1 with k = kappa, k' =
      // kappa'.
      const int    n  = n_;
      const double k  = kappa;
      const double kp = kappa * wave_speed_ratio();

      const double jl = bessel_j(n, k), djl = bessel_j_derivative(n, k),
                   ddjl = bessel_j_second_derivative(n, k);
      const double jt = bessel_j(n, kp), djt = bessel_j_derivative(n, kp),
                   ddjt = bessel_j_second_derivative(n, kp);

      // f, f', g, g' at r = 1; index 0: coefficient of A, 1: of B.
      const double f[2]  = {k * djl, n * jt};
      const double df[2] = {k * k * ddjl, n * (kp * djt - jt)};
      const double g[2]  = {-n * jl, -kp * djt};
      const double dg[2] = {-n * (k * djl - jl), -kp * kp * ddjt};

      // sigma_rr / mu = (lambda/mu + 2) f' + (lambda/mu) (f + n g) / r,
      // sigma_rphi / mu = g' - g / r - n f / r   (Gerl & Zippelius 1999, eqs.
      // 15, 16).
      const double lambda_over_mu = 2. * nu2 / (1. - nu2);
      double       s_rr[2], s_rphi[2];
      for (unsigned int c = 0; c < 2; ++c)
        {
          s_rr[c] =
            (lambda_over_mu + 2.) * df[c] + lambda_over_mu * (f[c] + n * g[c]);
          s_rphi[c] = dg[c] - g[c] - n * f[c];
        }
      return s_rr[0] * s_rphi[1] - s_rr[1] * s_rphi[0];
    }

    double
    FreeDiskModes::printed_eq25(const unsigned int n_, const double k) const
    {
      const int    n  = n_;
      const double kp = k * wave_speed_ratio();
      const double a  = 1. - nu2;
      const double m  = 1. - double(n) * n;
      return a * a * m * k * kp * bessel_j(n - 1, k) * bessel_j(n - 1, kp) +
             a * (k * k - a * m * n) *
               (k * bessel_j(n - 1, k) * bessel_j(n, kp) +
                kp * bessel_j(n - 1, kp) * bessel_j(n, k)) +
             (k * k * k * k - 2. * (double(n) * n + n) * a * k * k) *
               bessel_j(n, k) * bessel_j(n, kp);
    }

    double
    FreeDiskModes::printed_eq20(const double k) const
    {
      // d J_1(kappa R) / dR + (nu / R) J_1(kappa R) at R = 1
      return k * bessel_j_derivative(1, k) + nu2 * bessel_j(1, k);
    }

    double
    FreeDiskModes::printed_eq21(const double kp) const
    {
      // d J_1(kappa' R) / dR - (nu / R) J_1(kappa' R) at R = 1
      return kp * bessel_j_derivative(1, kp) - nu2 * bessel_j(1, kp);
    }

    double
    FreeDiskModes::frequency_equation(const unsigned int n,
                                      const ModeFamily   family,
                                      const double       kappa) const
    {
      switch (family)
        {
          case ModeFamily::radial:
            // sigma_rr = 0 for u_r = -A k J_1(k r): k J_0(k) = (1 - nu2) J_1(k)
            return kappa * bessel_j(0, kappa) - (1. - nu2) * bessel_j(1, kappa);
          case ModeFamily::torsional:
            // sigma_rphi = 0 for u_phi = B k' J_1(k' r): J_2(k') = 0
            return bessel_j(2, kappa * wave_speed_ratio());
          case ModeFamily::mixed:
            return boundary_determinant(n, kappa);
          case ModeFamily::rigid:
          case ModeFamily::spheroidal:
            break;
        }
      throw std::invalid_argument(
        "frequency_equation: a disk's families are radial, torsional and "
        "mixed");
    }

    std::vector<double>
    FreeDiskModes::kappa_roots(const unsigned int n,
                               const ModeFamily   family,
                               const double       kappa_max) const
    {
      if ((n == 0) == (family == ModeFamily::mixed) ||
          family == ModeFamily::rigid)
        throw std::invalid_argument(
          "kappa_roots: n = 0 has the radial and torsional families, n >= 1 "
          "the mixed one");

      auto &cached = root_cache[{n, family}];
      if (cached.first < kappa_max)
        {
          // Scan for sign changes with a step well below the spacing of
          // the zeros of J_n(kappa'), then bracket each root to machine
          // precision; continue where the last scan stopped. The mixed
          // family of order n has no root below kappa' = n / 2 (its lowest
          // mode runs along the edge faster than the Rayleigh speed,
          // kappa' > n c_R / c_T), and there the determinant, a product of
          // J_n ~ (kappa / 2)^n / n!, underflows to zero for large n: start
          // the scan there.
          const double step  = 0.01 / wave_speed_ratio();
          const double start = family == ModeFamily::mixed ?
                                 std::max(step, 0.5 * n / wave_speed_ratio()) :
                                 step;
          auto         f     = [&](const double k) {
            return frequency_equation(n, family, k);
          };
          cached.first = scan_roots(
            f, std::max(cached.first, start), kappa_max, step, cached.second);
        }
      std::vector<double> result;
      for (const double k : cached.second)
        if (k <= kappa_max)
          result.push_back(k);
      return result;
    }

    double
    FreeDiskModes::kappa(const ModeLabel &mode) const
    {
      // Roots already found (in ascending order) need no further scan.
      const auto &known = root_cache[{mode.n, mode.family}].second;
      if (known.size() > mode.l)
        return known[mode.l];
      double kappa_max = 4. + 2. * mode.n + 4. * mode.l;
      for (;;)
        {
          const auto roots = kappa_roots(mode.n, mode.family, kappa_max);
          if (roots.size() > mode.l)
            return roots[mode.l];
          kappa_max *= 2.;
        }
    }

    double
    FreeDiskModes::omega(const ModeLabel &mode) const
    {
      if (mode.family == ModeFamily::rigid)
        return 0.;
      return kappa(mode) * c_L / R;
    }

    std::vector<ModeLabel>
    FreeDiskModes::lowest_modes(const unsigned int n_modes,
                                const bool         half_domain) const
    {
      const unsigned int multiplicity = half_domain ? 1 : 2;
      for (double kappa_max = 4.;; kappa_max *= 1.5)
        {
          std::vector<std::pair<double, ModeLabel>> found;
          auto add_family = [&](const unsigned int n, const ModeFamily family) {
            const auto roots = kappa_roots(n, family, kappa_max);
            for (unsigned int l = 0; l < roots.size(); ++l)
              for (unsigned int c = 0; c < (n == 0 ? 1 : multiplicity); ++c)
                found.push_back({roots[l], ModeLabel{n, l, family}});
            return roots.size();
          };
          add_family(0, ModeFamily::radial);
          if (!half_domain)
            add_family(0, ModeFamily::torsional);
          // The lowest mode of order n rises with n (n >= 2): stop at the
          // first n without a root below kappa_max.
          for (unsigned int n = 1;; ++n)
            if (add_family(n, ModeFamily::mixed) == 0 && n >= 2)
              break;
          if (found.size() >= n_modes)
            return lowest_labels(found, n_modes);
        }
    }
  } // namespace Reference
} // namespace DiskImpact
