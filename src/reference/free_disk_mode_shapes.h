#pragma once

#include "reference/free_disk_modes.h"

#include <utility>
#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /// Radial profiles of a mode and their r-derivatives at one radius.
    struct RadialProfile
    {
      double u_r       = 0.; ///< u_r^{n,l}(r), the factor of cos(n phi)
      double du_r_dr   = 0.;
      double u_phi     = 0.; ///< u_phi^{n,l}(r), the factor of sin(n phi)
      double du_phi_dr = 0.;
    };

    /// A mode label with the root kappa = omega R / c_L of its equation.
    struct LabelledKappa
    {
      ModeLabel label;
      double    kappa = 0.;
    };

    /**
     * The lowest @p n_modes elastic modes of the set symmetric about the
     * impact axis (radial family n = 0, mixed family n >= 1, each once), in
     * ascending frequency, with their roots:
     * FreeDiskModes::lowest_modes(n_modes, true) and FreeDiskModes::kappa().
     */
    std::vector<LabelledKappa>
    lowest_symmetric_modes(const FreeDiskModes &modes, unsigned int n_modes);

    /**
     * Shape of one free-disk eigenmode of the set symmetric about the
     * impact axis (Gerl & Zippelius 1999, eqs. 19, 27 with the kappa/kappa' of
     * eq. 27 corrected): u_r   = [A k J_n'(k r) + n B J_n(k' r) / r] cos(n
     * phi), u_phi = -[n A J_n(k r) / r + B k' J_n'(k' r)] sin(n phi), k = kappa
     * / R, k' = kappa' / R. (A, B) is the null vector of the traction-free
     * conditions sigma_rr = sigma_rphi = 0 at r = R, scaled so that the
     * mass-weighted norm is that of the rigid translation: int_disk |u|^2 dA =
     * pi R^2, i.e. rho int |u|^2 dA = m (Gerl & Zippelius 1999, eq. 26 with R =
     * 1, valid for every mode of the set, n = 0 included). The modal coordinate
     * Q is then a length with modal mass m. Sign: the larger of the edge
     * amplitudes C, S (eq. 28) is positive.
     */
    class FreeDiskModeShape
    {
    public:
      /**
       * Mode @p mode (radial or mixed family) with the root @p kappa of its
       * frequency equation (FreeDiskModes::kappa), for in-plane Poisson
       * ratio @p in_plane_poisson_ratio and disk radius @p radius.
       */
      FreeDiskModeShape(double           in_plane_poisson_ratio,
                        double           radius,
                        const ModeLabel &mode,
                        double           kappa);

      const ModeLabel &
      label() const;

      /// The root kappa = omega R / c_L of the mode.
      double
      kappa() const;

      /// Coefficients (A, B) of Gerl & Zippelius 1999, eq. 27 (normalised).
      std::pair<double, double>
      coefficients() const;

      /// u_r^{n,l}, u_phi^{n,l} and their derivatives at radius @p r.
      RadialProfile
      profile(double r) const;

      /// C = u_r^{n,l}(R) (Gerl & Zippelius 1999, eq. 28).
      double
      edge_radial_amplitude() const;
      /// S = u_phi^{n,l}(R) (Gerl & Zippelius 1999, eq. 28).
      double
      edge_tangential_amplitude() const;

      /// Amplitudes of sigma_rr / E2 (of cos n phi) and sigma_rphi / E2 (of
      /// sin n phi) at r = R per unit modal coordinate Q / R; zero for an
      /// eigenmode (Gerl & Zippelius 1999, eqs. 15, 16 with sigma_rphi = 2 mu
      /// eps_rphi).
      std::pair<double, double>
      boundary_tractions() const;

      /// int_0^{2 pi} cos^2(n phi) d phi: 2 pi for n = 0, pi for n >= 1.
      double
      angular_norm_factor() const;

      /// int_0^R r (u_r^2 + u_phi^2) dr by Gauss-Legendre panels.
      double
      radial_mass_integral() const;

    private:
      double    nu2;
      double    R;
      ModeLabel mode;
      double    k;       ///< kappa / R
      double    k_prime; ///< kappa' / R
      double    A = 0.;
      double    B = 0.;

      /// Profile of the A-part (a = 1, b = 0) or B-part (a = 0, b = 1).
      RadialProfile
      profile(double r, double a, double b) const;

      /// (sigma_rr, sigma_rphi) / E2 at r = R for the given profile.
      std::pair<double, double>
      tractions(const RadialProfile &at_edge) const;
    };

    /// Shapes of the @p n_modes lowest modes of the symmetric set
    /// (lowest_symmetric_modes()) of a disk of radius 1.
    std::vector<FreeDiskModeShape>
    symmetric_mode_shapes(double in_plane_poisson_ratio, unsigned int n_modes);
  } // namespace Reference
} // namespace DiskImpact
