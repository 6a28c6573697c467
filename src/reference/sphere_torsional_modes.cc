#include "reference/sphere_torsional_modes.h"

#include "reference/root_scan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace DiskImpact
{
  namespace Reference
  {
    SphereTorsionalModes::SphereTorsionalModes(
      const double transverse_wave_speed,
      const double radius)
        : c_T(transverse_wave_speed)
        , R(radius)
    {
      if (!(c_T > 0.) || !(R > 0.))
        throw std::invalid_argument(
          "SphereTorsionalModes: need c_T > 0 and R > 0");
    }

    double
    SphereTorsionalModes::frequency_equation(const unsigned int n,
                                             const double       xi)
    {
      return (n - 1.) * std::sph_bessel(n, xi) -
             xi * std::sph_bessel(n + 1, xi);
    }

    std::vector<double>
    SphereTorsionalModes::xi_roots(const unsigned int n,
                                   const double       xi_max) const
    {
      if (n == 0)
        throw std::invalid_argument(
          "SphereTorsionalModes: torsional modes have degree n >= 1");
      auto &cached = root_cache[n];
      // The roots lie about pi apart; a step of 0.01 sees each one. The
      // scan starts past xi = 0 (n = 1's rigid rotation) and, for larger n,
      // at n / 2: the lowest root of degree n lies above n (a wave around
      // the surface no faster than c_T), and below, j_n ~ xi^n / (2n+1)!!
      // would underflow.
      const double step  = 0.01;
      const double start = std::max(step, 0.5 * n);
      if (cached.first < xi_max)
        cached.first =
          scan_roots([n](const double xi) { return frequency_equation(n, xi); },
                     std::max(cached.first, start),
                     xi_max,
                     step,
                     cached.second);
      std::vector<double> result;
      for (const double xi : cached.second)
        if (xi <= xi_max)
          result.push_back(xi);
      return result;
    }

    double
    SphereTorsionalModes::omega(const ModeLabel &mode) const
    {
      if (mode.family == ModeFamily::rigid)
        return 0.;
      if (mode.family != ModeFamily::torsional)
        throw std::invalid_argument(
          "SphereTorsionalModes: not a torsional mode (" +
          to_string(mode.family) + ")");
      for (double xi_max = 4. + 2. * mode.n + 4. * mode.l;; xi_max *= 2.)
        {
          const auto roots = xi_roots(mode.n, xi_max);
          if (roots.size() > mode.l)
            return roots[mode.l] * c_T / R;
        }
    }

    std::vector<ModeLabel>
    SphereTorsionalModes::lowest_modes(const unsigned int n_modes, bool) const
    {
      for (double xi_max = 6.;; xi_max *= 1.5)
        {
          // The lowest root of degree n rises with n: stop at the first
          // degree without a root below xi_max.
          std::vector<std::pair<double, ModeLabel>> found;
          for (unsigned int n = 1;; ++n)
            {
              const auto roots = xi_roots(n, xi_max);
              for (unsigned int l = 0; l < roots.size(); ++l)
                found.push_back(
                  {roots[l], ModeLabel{n, l, ModeFamily::torsional}});
              if (roots.empty() && n >= 2)
                break;
            }
          if (found.size() >= n_modes)
            return lowest_labels(found, n_modes);
        }
    }
  } // namespace Reference
} // namespace DiskImpact
