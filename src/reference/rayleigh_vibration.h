#pragma once

#include "reference/free_disk_mode_shapes.h"
#include "reference/free_disk_modes.h"

#include <stdexcept>
#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /// One mode's share of Rayleigh's estimate (energy / (m v^2 / 2)).
    struct RayleighModeEnergy
    {
      ModeLabel label;
      double    omega           = 0.;
      double    energy_fraction = 0.;
    };

    /// Rayleigh's estimate of the vibration one collision leaves behind.
    struct RayleighVibration
    {
      double contact_time    = 0.; ///< of the quasistatic 1-DOF collision
      double max_compression = 0.;
      /// Sum of the mode energies over the initial kinetic energy.
      double                          vibration_fraction = 0.;
      std::vector<RayleighModeEnergy> modes;

      /// epsilon = sqrt(1 - vibration fraction), first order in the
      /// vibration.
      double
      epsilon() const;
    };

    /**
     * Rayleigh's low-velocity estimate of the energy an elastic disk's
     * collision leaves in its vibrations (Gerl & Zippelius 1999, section 5,
     * eqs. 62-68): the quasistatic force P(t) of the 1-DOF collision m delta''
     * = -P(delta) (log law with the constant @p constant) acts at the contact
     * point phi = 0 on every mode of @p shapes, each an oscillator
     * m (Q'' + omega^2 Q) = -C P(t), C the mode's edge radial amplitude
     * (eq. 28; the shapes have modal mass m). After the collision the mode
     * holds E = C^2 |int_0^tc P e^{i omega t} dt|^2 / (2 m); the pulse is
     * symmetric about the turning time h = tc / 2, so
     *   E = 2 C^2 / m [int_0^h P(t) cos(omega (h - t)) dt]^2.
     * Units R = rho = E2 = 1 (m = pi, c = 1, omega = kappa c_L, c_L =
     * 1 / sqrt(1 - nu2^2)). The estimate is first order: the force does not
     * feel the vibration it excites, so it is the limit v -> 0 of the
     * dynamic collision, not its value at finite v.
     */
    RayleighVibration
    rayleigh_vibration(double velocity,
                       double constant,
                       double in_plane_poisson_ratio,
                       const std::vector<FreeDiskModeShape> &shapes);

    /// Thrown by rayleigh_impact() when the modes' quasistatic compliance
    /// exceeds the log law's at the collision's force.
    class TooManyModes : public std::domain_error
    {
    public:
      using std::domain_error::domain_error;
    };

    /// One collision of the quasistatic contact with vibration feedback.
    struct RayleighImpact
    {
      double epsilon            = 0.; ///< -v_com after / v before
      double contact_time       = 0.;
      double max_compression    = 0.; ///< largest approach of the centre
      double vibration_fraction = 0.; ///< mode energy after / (m v^2 / 2)
      double energy_error       = 0.; ///< |energy drift| / (m v^2 / 2)
    };

    /**
     * Rayleigh's model with the vibration fed back into the contact: the
     * centre of mass delta and the modes Q of @p shapes move as
     *   m delta'' = -P,   m (Q'' + omega^2 Q) = -C P,
     * and the contact force follows the log law of the local compression,
     * the centre's approach plus the dynamic part of the contact point's
     * modal displacement, u_dyn = sum C (Q - Q_qs), Q_qs = -C P / (m omega^2)
     * the modes' quasistatic response:
     *   D(P) = delta + u_dyn  <=>  D(P) - P S_N = delta + sum C Q,
     * D(P) = P/pi [ln(4 pi / P) + C_law] the law of the centre's approach,
     * S_N = sum C^2 / (m omega^2). D(P) - P S_N is the compliance of the
     * contact zone and of the modes left out; it must grow with P, which
     * bounds N by the contact width (a shortest modal wavelength well above
     * the Hertz half-width; TooManyModes otherwise). Without the feedback
     * (u_dyn = 0) this is rayleigh_vibration(); with it, the collision's
     * contact time, compression and epsilon keep the dynamics the 1-DOF model
     * omits. Classical RK4 with @p steps_per_period steps per shortest modal
     * period and at least 2000 per 1-DOF contact time; the collision ends when
     * the force returns to zero (Schwager & Pöschel 2007) and does not rise
     * again within a fifth of the contact time. Units R = rho = E2 = 1 (m = pi,
     * c = 1).
     */
    RayleighImpact
    rayleigh_impact(double velocity,
                    double constant,
                    double in_plane_poisson_ratio,
                    const std::vector<FreeDiskModeShape> &shapes,
                    double steps_per_period = 40.);
  } // namespace Reference
} // namespace DiskImpact
