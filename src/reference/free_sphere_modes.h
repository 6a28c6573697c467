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
     * Analytic eigenfrequencies of the axisymmetric (m = 0) spheroidal modes
     * of a free elastic sphere of radius R (Lamb, Proc. London Math. Soc. 13,
     * 1882).
     *
     * With u = grad phi + curl curl(x chi), phi = A j_n(h r) P_n(cos theta),
     * chi = B j_n(k r) P_n(cos theta), h = omega / c_L, k = omega / c_T, the
     * displacement is u_r = U(r) P_n, u_theta = V(r) dP_n/dtheta with
     *   U = A f' + B n(n+1) g / r,   V = A f / r + B (r g)' / r,
     * f = j_n(h r), g = j_n(k r), and div u = -h^2 phi. The traction-free
     * conditions at r = R,
     *   sigma_rr     = -lambda h^2 A f + 2 mu U' = 0,
     *   sigma_rtheta = mu (U / r + V' - V / r) P_n' = 0,
     * are a 2x2 system in (A, B) whose determinant vanishes at the
     * eigenfrequencies (n >= 1); for n = 0 (u_theta = 0) the first condition
     * alone. Derived here from the stresses, not copied from a printed
     * frequency equation.
     *
     * kappa = omega R / c_L, as for the disk; the mode (n, l) has
     * u_r ~ P_n(cos theta) on the surface and z-parity (-1)^n about the
     * equator.
     */
    class FreeSphereModes : public FreeBodyModes
    {
    public:
      /// @p poisson_ratio nu (3D), @p longitudinal_wave_speed
      /// c_L = sqrt((lambda + 2 mu) / rho), @p radius R.
      FreeSphereModes(double poisson_ratio,
                      double longitudinal_wave_speed,
                      double radius);

      /// Frequency equation of degree n at kappa; zero at the
      /// eigenfrequencies.
      double
      frequency_equation(unsigned int n, double kappa) const;

      /// All roots kappa in (0, kappa_max] of degree n, ascending.
      std::vector<double>
      kappa_roots(unsigned int n, double kappa_max) const;

      /// kappa of mode (n, l).
      double
      kappa(const ModeLabel &mode) const;
      double
      omega(const ModeLabel &mode) const override;

      /// Ratio c_L / c_T = sqrt(2 (1 - nu) / (1 - 2 nu)).
      double
      wave_speed_ratio() const;

      /// The lowest @p n_modes elastic modes, each degree n once (m = 0);
      /// @p half_domain is irrelevant (the meridian holds every m = 0 mode).
      std::vector<ModeLabel>
      lowest_modes(unsigned int n_modes, bool half_domain) const override;

      /// The family of degree n: radial (n = 0) or spheroidal.
      static ModeFamily
      family(unsigned int n);

    private:
      double nu;
      double c_L;
      double R;

      /// Roots found so far per degree, and the kappa the scan has reached.
      mutable std::map<unsigned int, std::pair<double, std::vector<double>>>
        root_cache;
    };
  } // namespace Reference
} // namespace DiskImpact
