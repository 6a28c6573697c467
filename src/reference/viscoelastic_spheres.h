#pragma once

#include "reference/collision_ode.h"

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * The Hertz law of two elastic spheres (Ramírez et al. 1999, eq. 2) as a
     * force law: F(xi) = rho xi^{3/2}, F'(xi) = (3/2) rho xi^{1/2}; zero for xi
     * <= 0. With the dissipation A of collide() it gives the viscoelastic force
     * of eq. 3, (3/2) A rho xi' xi^{1/2} (eq. 13).
     */
    ForceLaw
    hertz_force_law(double rho);

    /**
     * C_1 = sqrt(pi) Gamma(3/5) / (2^{1/5} 5^{2/5} Gamma(21/10))
     * = 1.1534489 (Ramírez et al. 1999, eqs. 30-31): (g / g*)^{1/5} = C_1 (3/2)
     * A (rho / m_eff)^{2/5} g^{1/5}.
     */
    double
    sphere_c1();

    /**
     * The characteristic velocity g* of Ramírez et al. 1999, eq. 30:
     * (g*)^{-1/5} = C_1 (3/2) A (rho / m_eff)^{2/5}.
     */
    double
    sphere_characteristic_velocity(double effective_mass,
                                   double rho,
                                   double dissipation);

    /**
     * The expansion variable of Ramírez et al. 1999, eq. 32: u = (g / g*)^{1/5}
     * = C_1 (3/2) A (rho / m_eff)^{2/5} g^{1/5}, for the impact velocity
     * @p velocity = g. The restitution coefficient of m_eff xi'' +
     * rho xi^{3/2} + (3/2) A rho xi' xi^{1/2} = 0 depends on the parameters
     * only through u (eqs. 11, 14-15).
     */
    double
    sphere_scaled_velocity(double effective_mass,
                           double rho,
                           double dissipation,
                           double velocity);

    /**
     * The coefficients of the series eq. 32,
     * epsilon = 1 - a_1 u + a_2 u^2 - a_3 u^3 + a_4 u^4 + ...
     */
    struct SphereSeriesCoefficients
    {
      double a1;
      double a2;
      double a3;
      double a4;
    };

    /**
     * The coefficients as verified (docs/theory/viscoelastic-spheres.md):
     * a_1 = 1, a_2 = 3/5 (exact), a_3 = 0.3407290, a_4 = 0.1970206 (the
     * appendix's route with correct y_2, y_3, confirmed by a least-squares
     * fit of the ODE's epsilon).
     */
    constexpr SphereSeriesCoefficients
      verified_sphere_coefficients{1., 0.6, 0.3407290271, 0.1970206380};

    /// The coefficients as printed in Ramírez et al. 1999, eq. 33 (for the
    /// misprint record): a_3 = 0.315119, a_4 = 0.161167, both wrong.
    constexpr SphereSeriesCoefficients printed_sphere_coefficients{1.,
                                                                   0.6,
                                                                   0.315119,
                                                                   0.161167};

    /**
     * The coefficient of the first half-integer power in the force
     * criterion's series, (4/15) C_1^{-5/2} = 0.1866263: after the total
     * force vanishes at xi = (3/2) A |xi'|, the overlap criterion would let
     * the attractive force act until xi = 0 and remove
     * (4/15) (u / C_1)^{5/2} epsilon^{3/2} + O(u^5) from epsilon.
     */
    double
    sphere_delayed_recovery_coefficient();

    /**
     * epsilon(u) from the series of Ramírez et al. 1999, eq. 32, to fourth
     * order. EndCriterion::overlap gives eq. 32 itself, the paper's setting
     * (eq. 10 ends the collision at xi = 0); its first omitted term is -a_5
     * u^5, a_5 = 0.117. EndCriterion::force adds the delayed-recovery terms k
     * u^{5/2} (1 - (3/2) u), k = sphere_delayed_recovery_coefficient(); its
     * first omitted term is (51/40) k u^{9/2}.
     */
    double
    sphere_restitution_series(double                          scaled_velocity,
                              EndCriterion                    end,
                              const SphereSeriesCoefficients &coefficients =
                                verified_sphere_coefficients);

    /// The coefficients d_1 ... d_5 of the Pade approximant eq. 35.
    struct SpherePadeCoefficients
    {
      double d1;
      double d2;
      double d3;
      double d4;
      double d5;
    };

    /**
     * d_1 ... d_5 from a_2, a_3, a_4 by Ramírez et al. 1999, Table I (a_1 = 1):
     * the [1/4] Pade approximant that matches eq. 32 through u^4 and has a zero
     * u^5 coefficient (a_5 = 0).
     */
    SpherePadeCoefficients
    sphere_pade_coefficients(const SphereSeriesCoefficients &coefficients);

    /**
     * epsilon(u) from the Pade approximant of Ramírez et al. 1999, eq. 35,
     * (1 + d_1 u) / (1 + d_2 u + d_3 u^2 + d_4 u^3 + d_5 u^4), with the d_k
     * of sphere_pade_coefficients().
     */
    double
    sphere_restitution_pade(double                          scaled_velocity,
                            const SphereSeriesCoefficients &coefficients =
                              verified_sphere_coefficients);

    /**
     * epsilon(u) from the collision ODE (Ramírez et al. 1999, eq. 5) by
     * collide(), in units m_eff = rho = g = 1, where A = u / ((3/2) C_1).
     */
    double
    sphere_restitution_ode(double       scaled_velocity,
                           EndCriterion end,
                           double       tolerance = 1e-13);
  } // namespace Reference
} // namespace DiskImpact
