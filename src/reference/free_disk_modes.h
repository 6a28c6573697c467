#pragma once

#include "reference/free_body_modes.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * Analytic eigenfrequencies of a free elastic disk of radius R.
     *
     * With u = grad Phi + curl(Psi e_z), Phi = A J_n(k r) cos(n phi) and
     * Psi = B J_n(k' r) sin(n phi) (Gerl & Zippelius 1999, eqs. 17-19), the
     * traction-free conditions sigma_rr = sigma_rphi = 0 at r = R are a 2x2
     * linear system in (A, B); its determinant vanishes at the
     * eigenfrequencies. Here the determinant is built directly from the
     * stresses (Gerl & Zippelius 1999, eq. 16), not copied from the printed eq.
     * 25; the printed forms of eqs. 20, 21 and 25 are kept for comparison (see
     * docs/theory/misprints.md).
     *
     * kappa = omega R / c_L is Gerl & Zippelius' dimensionless wave number (eq.
     * 18 with R = 1), kappa' = kappa c_L / c_T.
     */
    class FreeDiskModes : public FreeBodyModes
    {
    public:
      /**
       * @p in_plane_poisson_ratio nu2, @p longitudinal_wave_speed
       * c_L = sqrt(E2 / ((1 - nu2^2) rho)), @p radius R.
       */
      FreeDiskModes(double in_plane_poisson_ratio,
                    double longitudinal_wave_speed,
                    double radius);

      /// Frequency equation of a family at wave number kappa; zero at the
      /// eigenfrequencies. For n >= 1 the boundary determinant; for n = 0
      /// the radial factor kappa J_0(kappa) - (1 - nu2) J_1(kappa) or the
      /// torsional factor J_2(kappa').
      double
      frequency_equation(unsigned int n, ModeFamily family, double kappa) const;

      /// det of the traction-free boundary conditions at r = R (any n).
      double
      boundary_determinant(unsigned int n, double kappa) const;

      /// Gerl & Zippelius' eq. 25 as printed.
      double
      printed_eq25(unsigned int n, double kappa) const;
      /// Gerl & Zippelius' eq. 20 as printed (radial family, R = 1).
      double
      printed_eq20(double kappa) const;
      /// Gerl & Zippelius' eq. 21 as printed (torsional family, argument
      /// kappa').
      double
      printed_eq21(double kappa_prime) const;

      /// All roots kappa in (0, kappa_max] of a family's frequency equation,
      /// ascending.
      std::vector<double>
      kappa_roots(unsigned int n, ModeFamily family, double kappa_max) const;

      /// kappa of mode (n, l, family).
      double
      kappa(const ModeLabel &mode) const;
      /// Angular frequency omega = kappa c_L / R of mode (n, l, family).
      double
      omega(const ModeLabel &mode) const override;

      /// Ratio c_L / c_T = sqrt(2 / (1 - nu2)).
      double
      wave_speed_ratio() const;

      /**
       * The lowest @p n_modes elastic modes in ascending frequency, each
       * n >= 1 mode listed twice for the full disk (cos and sin
       * orientation). For the half disk (symmetric about the impact axis)
       * only the orientation with u_r even in phi exists: n >= 1 once and no
       * torsional modes.
       */
      std::vector<ModeLabel>
      lowest_modes(unsigned int n_modes, bool half_domain) const override;

    private:
      double nu2;
      double c_L;
      double R;

      /// Roots already found, per (n, family), and the kappa they cover.
      mutable std::map<std::pair<unsigned int, ModeFamily>,
                       std::pair<double, std::vector<double>>>
        root_cache;
    };
  } // namespace Reference
} // namespace DiskImpact
