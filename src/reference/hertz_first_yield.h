#pragma once

namespace DiskImpact
{
  namespace Reference
  {
    /// Where and at which peak pressure p0 a Hertz contact first yields
    /// (von Mises with yield stress Y).
    struct FirstYield
    {
      double pressure_ratio; ///< p0 / Y at first yield
      double depth;          ///< z / a of the first plastic point
    };

    /**
     * The von Mises stress over p0 on the axis of a sphere's Hertz contact
     * (radius a) at the depth @p z (over a), Poisson ratio @p nu: with
     * s = z / a (Johnson, Contact Mechanics, 1985, eq. 3.45),
     *
     *   sigma_r = sigma_theta = -p0 [(1 + nu)(1 - s arctan(1/s))
     *                                - 1 / (2 (1 + s^2))],
     *   sigma_z = -p0 / (1 + s^2),
     *
     * principal stresses, so the von Mises stress is |sigma_r - sigma_z|.
     */
    double
    sphere_axis_von_mises(double z, double nu);

    /**
     * The von Mises stress over p0 in the half-plane under Hertz's 2D
     * pressure p0 sqrt(1 - x^2/a^2), at (@p x, @p z) over a, with the
     * out-of-plane stress sigma_yy = @p out_of_plane_ratio (sigma_xx +
     * sigma_zz): nu in plane strain, 0 in plane stress. The in-plane field
     * does not depend on the elastic constants (McEwen 1949; Johnson 1985,
     * eq. 4.49): with m, n >= 0 from
     * m^2 - n^2 = 1 - x^2 + z^2, m n = |x| z (over a^2),
     *
     *   sigma_xx = -p0 [m (1 + (z^2 + n^2) / (m^2 + n^2)) - 2 z],
     *   sigma_zz = -p0 m (1 - (z^2 + n^2) / (m^2 + n^2)),
     *   tau_xz   =  p0 n (m^2 - z^2) / (m^2 + n^2)  (sign of x).
     */
    double
    half_plane_von_mises(double x, double z, double out_of_plane_ratio);

    /// The largest sphere_axis_von_mises() over the depth: first yield at
    /// p0 / Y = 1 / that maximum.
    FirstYield
    sphere_first_yield(double nu);

    /// The largest half_plane_von_mises() on the axis x = 0 (where the
    /// half-plane's largest value lies, checked by the unit tests): below
    /// the surface in plane strain (p0 = 1.79 Y at z = 0.70 a, nu = 0.3),
    /// at the surface in plane stress (p0 = Y, sigma_xx = sigma_zz = -p0).
    FirstYield
    half_plane_first_yield(double out_of_plane_ratio);

    /**
     * The speed v_y / c of a sphere on a rigid wall at which Hertz's peak
     * pressure reaches @p pressure_ratio Y, for the yield strain
     * @p yield_strain = Y / E* (c = sqrt(E* / rho), E* = E / (1 - nu^2)):
     * m v_y^2 / 2 = (8/15) E* R^{1/2} delta_y^{5/2} with
     * delta_y = R (pi p0 / (2 E*))^2 and m = (4/3) pi R^3 rho give
     *
     *   v_y / c = sqrt(4 / (5 pi)) (pi p0 / (2 E*))^{5/2}
     *
     * (Johnson 1985, eq. 11.24: rho v_y^2 / Y = 26 (Y / E*)^4 for p0 = 1.6 Y).
     */
    double
    sphere_yield_velocity(double pressure_ratio, double yield_strain);

    /**
     * The speed v_y / c of a disk on a rigid wall (per unit thickness,
     * c = sqrt(E2 / rho)) at which Hertz's peak pressure p0 = sqrt(P E2 /
     * (pi R)) reaches @p pressure_ratio Y, with @p yield_strain = Y / E2 and
     * the disk's law d = x [ln(4/x) + C] for the approach of the centre of
     * mass (@p law_constant = C_com): the work
     * int P d delta = pi E2 R^2 x_y^2 [ln(4/x_y) + C - 1/2] / 2 up to
     * x_y = P_y / (pi E2 R) = (p0 / E2)^2 equals m v_y^2 / 2 with
     * m = rho pi R^2, so
     *
     *   v_y / c = x_y sqrt(ln(4 / x_y) + C - 1/2).
     */
    double
    disk_yield_velocity(double pressure_ratio,
                        double yield_strain,
                        double law_constant);
  } // namespace Reference
} // namespace DiskImpact
