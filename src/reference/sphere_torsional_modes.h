#pragma once

#include "reference/free_body_modes.h"

#include <map>
#include <utility>
#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * Analytic eigenfrequencies of the axisymmetric (m = 0) torsional modes
     * of a free elastic sphere of radius R (Lamb, Proc. London Math. Soc.
     * 13, 1882): the azimuthal displacement u_phi = j_n(k r) dP_n/dtheta,
     * k = omega / c_T, n >= 1, with the only traction
     * sigma_{r phi} = mu (du_phi/dr - u_phi / r). Its zero at r = R,
     * xi j_n'(xi) - j_n(xi) = 0 with j_n' = (n / xi) j_n - j_{n+1}, is
     *
     *   (n - 1) j_n(xi) - xi j_{n+1}(xi) = 0,    xi = omega R / c_T.
     *
     * For n = 1 the root xi = 0 is the rigid rotation about the axis; the
     * elastic roots are those of j_2. The frequencies do not depend on nu.
     * On the surface u_phi ~ dP_n/dtheta, whose z-parity about the equator
     * is (-1)^(n-1).
     */
    class SphereTorsionalModes : public FreeBodyModes
    {
    public:
      /// @p transverse_wave_speed c_T = sqrt(mu / rho), @p radius R.
      SphereTorsionalModes(double transverse_wave_speed, double radius);

      /// The frequency equation of degree n at xi; zero at the
      /// eigenfrequencies.
      static double
      frequency_equation(unsigned int n, double xi);

      /// The roots xi in (0, xi_max] of degree n, ascending (xi = 0 of
      /// n = 1 excluded).
      std::vector<double>
      xi_roots(unsigned int n, double xi_max) const;

      /// omega of mode (n, l, torsional); 0 for rigid modes.
      double
      omega(const ModeLabel &mode) const override;

      /// The lowest @p n_modes torsional modes, ascending.
      std::vector<ModeLabel>
      lowest_modes(unsigned int n_modes,
                   bool         half_domain = false) const override;

    private:
      double c_T;
      double R;

      /// Roots found so far per degree, and the xi the scan has reached.
      mutable std::map<unsigned int, std::pair<double, std::vector<double>>>
        root_cache;
    };
  } // namespace Reference
} // namespace DiskImpact
