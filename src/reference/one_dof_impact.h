#pragma once

namespace DiskImpact
{
  namespace Reference
  {
    /// Contact time, largest compression and force of a 1-DOF collision.
    struct OneDofImpact
    {
      double contact_time    = 0.;
      double max_compression = 0.;
      double max_force       = 0.;
    };

    /**
     * The quasistatic 1-DOF collision m delta'' = -P(delta) of a disk with
     * the wall, P(delta) the inverse of the log law
     * delta/R = x [ln(4/x) + C], x = P/(pi E2 R) (Schwager 2007, eqs. 2-3;
     * Gerl & Zippelius 1999, eq. 57 with the constant C). It is elastic
     * (epsilon = 1); energy conservation gives V(delta_max) = m v^2 / 2 with
     * V(delta) = int_0^delta P, and the contact time is
     * 2 int_0^delta_max d delta / sqrt(v^2 - 2 V(delta) / m).
     * Per unit thickness: @p mass = rho pi R^2, P per unit thickness.
     */
    OneDofImpact
    one_dof_impact(double velocity,
                   double mass,
                   double in_plane_young_modulus,
                   double radius,
                   double constant);
  } // namespace Reference
} // namespace DiskImpact
