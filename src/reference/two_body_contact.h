#pragma once

#include "reference/collision_ode.h"
#include "reference/one_dof_impact.h"

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * One of two bodies pressed together head-on, as its own wall law sees
     * it: the radius R, the modulus (the in-plane E2 of a disk, Hertz's
     * E* = E / (1 - nu^2) of a sphere) and the constant of its wall law for
     * the approach of the centre of mass (the disk's C of LogContactLaw, the
     * sphere's D of sphere_force_law). A rigid body has an infinite modulus,
     * a flat one an infinite radius.
     */
    struct ContactBody
    {
      double radius   = 1.;
      double modulus  = 1.;
      double constant = 0.;
    };

    /**
     * The single body on a rigid wall whose wall law is the two bodies' law
     * (docs/theory/two-body-law.md): 1/R_eff = 1/R_1 + 1/R_2,
     * 1/E_eff = 1/E_1 + 1/E_2, and with the weights w_i = E_eff / E_i
     *
     *   disks:   C_eff = sum_i w_i [C_i + 2 ln(R_i / R_eff)],
     *   spheres: D_eff = sum_i w_i (R_eff / R_i) D_i,
     *
     * a rigid body (w_i = 0) adding nothing. Throws std::invalid_argument
     * for a non-positive radius or modulus, two rigid or two flat bodies,
     * or an elastic flat disk (an elastic half-plane has no finite
     * approach).
     */
    ContactBody
    equivalent_body(bool sphere, const ContactBody &b1, const ContactBody &b2);

    /**
     * Hertz's half-width (disk) or contact radius (sphere) of two bodies
     * pressed together by @p force (per unit thickness for disks), with the
     * combined curvature and compliance: a^2 = 4 P R_eff / (pi E_eff)
     * (Gerl & Zippelius 1999, eq. 48), a^3 = 3 P R_eff / (4 E_eff).
     */
    double
    two_body_half_width(bool               sphere,
                        double             force,
                        const ContactBody &b1,
                        const ContactBody &b2);

    /**
     * The approach delta = delta_1 + delta_2 of the centres of mass of two
     * disks pressed together by the force @p force per unit thickness, each
     * with its own wall law at the common Hertz half-width a
     * (two_body_half_width(); docs/theory/two-body-law.md):
     *
     *   delta = sum_i P / (pi E2_i) [2 ln(4 R_i / a) + C_i]
     *
     * (each term is the law delta/R = x [ln(4/x) + C] of LogContactLaw
     * written with a; Gerl & Zippelius 1999, eq. 57). Zero for @p force = 0.
     */
    double
    two_disk_approach(double             force,
                      const ContactBody &b1,
                      const ContactBody &b2);

    /**
     * The approach of the centres of two spheres pressed together by
     * @p force: Hertz's approach of the pair plus each sphere's finite-size
     * term (docs/theory/sphere-finite-size.md, docs/theory/two-body-law.md),
     *
     *   delta = a^2 / R_eff + sum_i D_i P / (E*_i R_i),
     *
     * a the common contact radius (two_body_half_width()). Zero for
     * @p force = 0.
     */
    double
    two_sphere_approach(double             force,
                        const ContactBody &b1,
                        const ContactBody &b2);

    /**
     * The constant of a body's wall law read off its share @p approach of
     * the approach (its contact centre's displacement toward the other
     * body relative to its centre of mass) under the force @p force with
     * the Hertz pressure of half-width (contact radius) @p a; the inverse
     * of one term of two_disk_approach() or two_sphere_approach():
     *
     *   disk:   C = pi E approach / P - 2 ln(4 R / a),
     *   sphere: D = (approach - 3 P / (4 a E)) E R / P.
     *
     * With equivalent_body() and the pair's approach it gives the pair's
     * C_eff or D_eff (docs/theory/two-body-law.md). Only the radius and
     * modulus of @p body are used.
     */
    double
    wall_law_constant(bool               sphere,
                      double             force,
                      double             approach,
                      double             a,
                      const ContactBody &body);

    /**
     * The largest approach of the pair's law, where d delta / dP = 0: for
     * disks 4 R_eff e^{C_eff - 1} (LogContactLaw::maximum_compression()),
     * for spheres R_eff / (12 D_eff^2) if D_eff < 0, else infinity.
     */
    double
    two_body_largest_approach(bool               sphere,
                              const ContactBody &b1,
                              const ContactBody &b2);

    /**
     * The pair's force law F(delta) for collide(): the inverse of
     * two_disk_approach() or two_sphere_approach() on the rising branch,
     * zero for delta <= 0, and F' = 1 / (d delta / dP). It is the wall law
     * of equivalent_body() (disk_force_law(), inverted by the Lambert W
     * function; sphere_force_law(), TOMS 748). Force and derivative throw
     * std::domain_error for delta >= two_body_largest_approach().
     */
    ForceLaw
    two_body_force_law(bool               sphere,
                       const ContactBody &b1,
                       const ContactBody &b2);

    /**
     * The elastic 1-DOF collision of two bodies, mu delta'' = -F(delta) with
     * the reduced mass @p reduced_mass mu = m_1 m_2 / (m_1 + m_2) and the
     * relative speed of approach @p relative_speed, integrated by collide()
     * (no dissipation, ended when the overlap returns to zero, as
     * WallContactTheory::elastic_impact() for a sphere). Throws
     * std::domain_error if mu v^2 / 2 reaches the law's energy at its largest
     * approach (for disks, V = P delta / 2 - P^2 / (4 pi E_eff); for spheres,
     * V = 2 P delta / 5 + D_eff P^2 / (10 E_eff R_eff)).
     */
    OneDofImpact
    two_body_elastic_impact(bool               sphere,
                            double             reduced_mass,
                            double             relative_speed,
                            const ContactBody &b1,
                            const ContactBody &b2);
  } // namespace Reference
} // namespace DiskImpact
