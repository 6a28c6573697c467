#include "reference/hertz_first_yield.h"

#include <boost/math/tools/minima.hpp>

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    namespace
    {
      /// The von Mises stress of principal or general stresses.
      double
      von_mises(const double xx,
                const double yy,
                const double zz,
                const double xz)
      {
        return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) +
                                (zz - xx) * (zz - xx)) +
                         3. * xz * xz);
      }

      /// 1 / (the largest of @p f over the depth z in (0, 4), over a) and
      /// where: the subsurface maximum of a Hertz field lies near
      /// z = 0.5 a ... 0.8 a.
      template <typename Function>
      FirstYield
      deepest_maximum(const Function &f)
      {
        boost::uintmax_t iterations = 200;
        const auto       best       = boost::math::tools::brent_find_minima(
          [&](const double z) { return -f(z); }, 0., 4., 50, iterations);
        return {-1. / best.second, best.first};
      }
    } // namespace

    double
    sphere_axis_von_mises(const double z, const double nu)
    {
      const double s       = std::abs(z);
      const double cap     = 1. / (1. + s * s);
      const double arc     = s > 0. ? s * std::atan(1. / s) : 0.;
      const double sigma_r = -((1. + nu) * (1. - arc) - 0.5 * cap);
      const double sigma_z = -cap;
      return std::abs(sigma_r - sigma_z);
    }

    double
    half_plane_von_mises(const double x,
                         const double z,
                         const double out_of_plane_ratio)
    {
      const double s    = std::abs(z);
      const double b    = 1. - x * x + s * s;
      const double root = std::sqrt(b * b + 4. * x * x * s * s);
      const double m    = std::sqrt(0.5 * (root + b));
      const double n    = std::copysign(std::sqrt(0.5 * (root - b)), x);
      const double q    = (s * s + n * n) / (m * m + n * n);
      const double xx   = -(m * (1. + q) - 2. * s);
      const double zz   = -m * (1. - q);
      const double xz   = n * (m * m - s * s) / (m * m + n * n);
      return von_mises(xx, out_of_plane_ratio * (xx + zz), zz, xz);
    }

    FirstYield
    sphere_first_yield(const double nu)
    {
      return deepest_maximum(
        [nu](const double z) { return sphere_axis_von_mises(z, nu); });
    }

    FirstYield
    half_plane_first_yield(const double out_of_plane_ratio)
    {
      return deepest_maximum([out_of_plane_ratio](const double z) {
        return half_plane_von_mises(0., z, out_of_plane_ratio);
      });
    }

    double
    sphere_yield_velocity(const double pressure_ratio,
                          const double yield_strain)
    {
      if (!(pressure_ratio > 0.) || !(yield_strain > 0.))
        throw std::domain_error("sphere_yield_velocity: needs p0/Y > 0 and "
                                "Y/E* > 0");
      const double p0 = pressure_ratio * yield_strain;
      return std::sqrt(4. / (5. * M_PI)) * std::pow(0.5 * M_PI * p0, 2.5);
    }

    double
    disk_yield_velocity(const double pressure_ratio,
                        const double yield_strain,
                        const double law_constant)
    {
      const double p0  = pressure_ratio * yield_strain;
      const double x_y = p0 * p0;
      const double log = std::log(4. / x_y) + law_constant - 0.5;
      if (!(p0 > 0.) || !(log > 0.))
        throw std::domain_error("disk_yield_velocity: needs p0/Y > 0, "
                                "Y/E2 > 0 and a load on the law's physical "
                                "branch");
      return x_y * std::sqrt(log);
    }
  } // namespace Reference
} // namespace DiskImpact
