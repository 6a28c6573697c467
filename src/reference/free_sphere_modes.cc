#include "reference/free_sphere_modes.h"

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
      /// j_n'(x) = (n / x) j_n(x) - j_{n+1}(x)
      double
      spherical_bessel_derivative(const unsigned int n, const double x)
      {
        return n / x * std::sph_bessel(n, x) - std::sph_bessel(n + 1, x);
      }

      /// j_n''(x) from the spherical Bessel equation, x > 0.
      double
      spherical_bessel_second_derivative(const unsigned int n, const double x)
      {
        return -2. / x * spherical_bessel_derivative(n, x) -
               (1. - n * (n + 1.) / (x * x)) * std::sph_bessel(n, x);
      }
    } // namespace

    FreeSphereModes::FreeSphereModes(const double poisson_ratio,
                                     const double longitudinal_wave_speed,
                                     const double radius)
        : nu(poisson_ratio)
        , c_L(longitudinal_wave_speed)
        , R(radius)
    {
      if (!(nu > -1. && nu < 0.5) || !(c_L > 0.) || !(R > 0.))
        throw std::invalid_argument(
          "FreeSphereModes: need -1 < nu < 1/2, c_L > 0, R > 0");
    }

    double
    FreeSphereModes::wave_speed_ratio() const
    {
      return std::sqrt(2. * (1. - nu) / (1. - 2. * nu));
    }

    ModeFamily
    FreeSphereModes::family(const unsigned int n)
    {
      return n == 0 ? ModeFamily::radial : ModeFamily::spheroidal;
    }

    double
    FreeSphereModes::frequency_equation(const unsigned int n,
                                        const double       kappa) const
    {
      // On the unit sphere: h = kappa, k = kappa c_L / c_T; f = j_n(h r),
      // g = j_n(k r) and their r-derivatives at r = 1.
      const double h = kappa, k = kappa * wave_speed_ratio();
      const double f   = std::sph_bessel(n, h),
                   df  = h * spherical_bessel_derivative(n, h),
                   ddf = h * h * spherical_bessel_second_derivative(n, h);
      const double g   = std::sph_bessel(n, k),
                   dg  = k * spherical_bessel_derivative(n, k);
      const double lambda_over_mu = std::pow(wave_speed_ratio(), 2) - 2.;
      const double nn1            = n * (n + 1.);

      // sigma_rr / mu: -(lambda / mu) h^2 A f + 2 U', with
      // U' = A f'' + B n(n+1) (g' - g);
      // sigma_rtheta / mu: U + V' - V, with g'' from Bessel's equation:
      // A 2 (f' - f) + B ((2 n(n+1) - 2 - k^2) g - 2 g').
      const double s_rr[2]     = {-lambda_over_mu * h * h * f + 2. * ddf,
                                  2. * nn1 * (dg - g)};
      const double s_rtheta[2] = {2. * (df - f),
                                  (2. * nn1 - 2. - k * k) * g - 2. * dg};
      if (n == 0)
        return s_rr[0];
      return s_rr[0] * s_rtheta[1] - s_rr[1] * s_rtheta[0];
    }

    std::vector<double>
    FreeSphereModes::kappa_roots(const unsigned int n,
                                 const double       kappa_max) const
    {
      auto &cached = root_cache[n];
      if (cached.first < kappa_max)
        {
          // As for the disk: a step well below the spacing of the zeros of
          // j_n(k), and for n >= 1 no root below k = n / 2 (the lowest mode
          // of degree n is a surface wave slower than c_T, k R > n c_R/c_T),
          // where the determinant, a product of j_n ~ x^n / (2n+1)!!,
          // underflows.
          const double step  = 0.01 / wave_speed_ratio();
          const double start = std::max(step, 0.5 * n / wave_speed_ratio());
          cached.first =
            scan_roots([&](const double x) { return frequency_equation(n, x); },
                       std::max(cached.first, start),
                       kappa_max,
                       step,
                       cached.second);
        }
      std::vector<double> result;
      for (const double k : cached.second)
        if (k <= kappa_max)
          result.push_back(k);
      return result;
    }

    double
    FreeSphereModes::kappa(const ModeLabel &mode) const
    {
      if (mode.family != family(mode.n))
        throw std::invalid_argument(
          "FreeSphereModes: degree " + std::to_string(mode.n) +
          " belongs to family " + to_string(family(mode.n)));
      for (double kappa_max = 4. + 2. * mode.n + 4. * mode.l;; kappa_max *= 2.)
        {
          const auto roots = kappa_roots(mode.n, kappa_max);
          if (roots.size() > mode.l)
            return roots[mode.l];
        }
    }

    double
    FreeSphereModes::omega(const ModeLabel &mode) const
    {
      if (mode.family == ModeFamily::rigid)
        return 0.;
      return kappa(mode) * c_L / R;
    }

    std::vector<ModeLabel>
    FreeSphereModes::lowest_modes(const unsigned int n_modes, bool) const
    {
      for (double kappa_max = 4.;; kappa_max *= 1.5)
        {
          std::vector<std::pair<double, ModeLabel>> found;
          // The lowest mode of degree n rises with n (n >= 2): stop at the
          // first degree without a root below kappa_max.
          for (unsigned int n = 0;; ++n)
            {
              const auto roots = kappa_roots(n, kappa_max);
              for (unsigned int l = 0; l < roots.size(); ++l)
                found.push_back({roots[l], ModeLabel{n, l, family(n)}});
              if (roots.empty() && n >= 2)
                break;
            }
          if (found.size() >= n_modes)
            return lowest_labels(found, n_modes);
        }
    }
  } // namespace Reference
} // namespace DiskImpact
