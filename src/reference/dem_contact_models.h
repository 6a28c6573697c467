#pragma once

#include "reference/collision_ode.h"

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * LIGGGHTS' Hertz model ('pair_style gran model hertz' with the
     * property 'coefficientRestitution' e) for a sphere on a rigid wall, or
     * two identical spheres (the same problem): the force
     *
     *   F = (4/3) Y* sqrt(R* d) d + 2 sqrt(5/6) |beta| sqrt(S_n m*) d',
     *   S_n = 2 Y* sqrt(R* d),  beta = ln e / sqrt(ln^2 e + pi^2),
     *
     * until the overlap d returns to zero. Its damping scales like the Hertz
     * stiffness, so its restitution does not depend on the speed; it is
     * close to e but not equal (beta is the linear spring's).
     */
    double
    liggghts_hertz_epsilon(double coefficient_restitution);

    /// The 'coefficientRestitution' for which liggghts_hertz_epsilon() is
    /// @p epsilon (0 < epsilon <= 1).
    double
    liggghts_hertz_input(double epsilon);

    /**
     * The viscoelastic sphere (Brilliantov et al., Ramírez et al. 1999) in
     * LAMMPS' 'pair_style granular' ('hertz/material E eta_n0 nu ... damping
     * viscoelastic'): LAMMPS's damping force eta_n0 a m_eff d' with the
     * contact radius a = sqrt(R_eff d) equals A dF/dt = 2 A E_eff a d' of
     * Ramírez et al. 1999 for eta_n0 = 2 A E_eff / m_eff.
     */
    /// Restitution and contact time (overlap back to zero) of a collision.
    struct LinearDashpotCollision
    {
      double epsilon;
      double contact_time;
    };

    /**
     * Yade's ViscElMat ('Law2_ScGeom_ViscElPhys_Basic'): a linear spring
     * k d + c d' with k and c set from the inputs (en, tc) by the classical
     * formulas of the undamped end (overlap back to zero), but a force that
     * is never attractive: the collision ends when k d + c d' = 0, and the
     * bodies fly apart from there. With the damping ratio
     * zeta = -ln en / sqrt(pi^2 + ln^2 en), w_d = pi / tc and
     * b = zeta / sqrt(1 - zeta^2), the force vanishes at the phase
     * th = pi - atan2(2 zeta sqrt(1 - zeta^2), 1 - 2 zeta^2), so
     *
     *   epsilon = e^{-b th} (b sin th - cos th),
     *   t_c     = (th + sin th / (b sin th - cos th)) / w_d,
     *
     * t_c counting the free flight until the overlap is zero. epsilon
     * exceeds en (by 1.6e-4 at en = 0.97).
     */
    LinearDashpotCollision
    yade_viscel_collision(double en, double tc);

    /// The inputs (en, tc) of ViscElMat for which yade_viscel_collision()
    /// gives @p epsilon (0 < epsilon <= 1) and @p contact_time.
    LinearDashpotCollision
    yade_viscel_inputs(double epsilon, double contact_time);

    /**
     * A linear spring-dashpot F = k d + eta d' between bodies of effective
     * mass m (LAMMPS' 'hooke k eta' with 'damping velocity'), the force
     * allowed to pull, the collision ended when the overlap d returns to
     * zero: m d'' + eta d' + k d = 0 gives the restitution epsilon and the
     * contact time t_c for
     *
     *   k = m (pi^2 + ln^2 epsilon) / t_c^2,   eta = -2 m ln(epsilon) / t_c.
     */
    struct LinearSpringDashpot
    {
      double stiffness;
      double damping;
    };

    LinearSpringDashpot
    linear_spring_dashpot(double epsilon,
                          double contact_time,
                          double effective_mass);

    double
    lammps_viscoelastic_damping(double dissipative_constant,
                                double effective_modulus,
                                double effective_mass);

    /**
     * LIGGGHTS' elastic-plastic contact 'pair_style gran model
     * thornton_ning' without adhesion ('surfaceEnergy' 0), for a sphere of
     * radius R on a rigid wall or two identical spheres (the same problem),
     * with the contact radius of yield a_y = r R ('coefficientYieldRatio'
     * r; Thornton's limiting pressure p_y = 2 E* a_y / (pi R)):
     *
     * - loading: Hertz's F = (4/3) E* R^{1/2} d^{3/2} up to
     *   d_y = a_y^2 / R, then Thornton's F = F_y + pi p_y R (d - d_y);
     * - unloading (and reloading): Hertz's stiffness of the current
     *   overlap, dF = 2 E* (R d)^{1/2} dd, with the original radius
     *   (LIGGGHTS integrates it in increments; Thornton 1997's unloading
     *   with an enlarged radius differs), until F = 0 at d_p.
     *
     * In units of d_y and F_y (x = d / d_y, f = F / F_y): loading
     * f = x^{3/2}, then f = 1 + (3/2)(x - 1); unloading
     * f = f_m - (x_m^{3/2} - x^{3/2}). The speed v_y at which the overlap
     * just reaches d_y stores W_y = 2/5, so at u = v / v_y the work of
     * loading 2/5 + y + (3/4) y^2 = (2/5) u^2 (y = x_m - 1) gives
     *
     *   x_m = 1 + (sqrt(6 u^2/5 - 1/5) - 1) / (3/2),
     *   x_p^{3/2} = x_m^{3/2} - f_m,
     *   epsilon^2 = [f_m (x_m - x_p) - x_m^{3/2} (x_m - x_p)
     *                + (2/5)(x_m^{5/2} - x_p^{5/2})] / ((2/5) u^2);
     *
     * epsilon = 1 for u <= 1 and epsilon ~ u^{-1/4} for u >> 1. v_y is
     * sphere_yield_velocity() of the pressure p_y.
     */
    double
    thornton_ning_epsilon(double speed_over_yield_speed);

    /**
     * Luding's elastic-plastic contact as Yade's LudingMat has it without
     * adhesion (kc = 0) and viscosity (G0 = 0), a linear hysteretic spring
     * after Walton and Braun, for a sphere on a rigid wall or two identical
     * spheres: loading F = k1 d; unloading and reloading F = k2 (d - d0),
     * d0 = (1 - k1/k2) d_max, with k2 = k1 + (kp - k1) d_max / d_p growing
     * with the largest overlap up to kp at the plasticity depth d_p; beyond
     * d_p loading and unloading follow F = kp (d - d_p0),
     * d_p0 = (1 - k1/kp) d_p. With a = kp/k1 - 1 and x = v / v_p (v_p the
     * speed whose largest overlap is d_p):
     *
     *   epsilon = (1 + a x)^{-1/2}             for x <= 1,
     *   epsilon = (1 - a / ((1 + a) x^2))^{1/2} for x > 1
     *
     * (beyond v_p the loss stays the loop up to d_p, k1 d_p^2 a / (2(1+a))).
     */
    double
    luding_epsilon(double speed_over_plastic_speed, double stiffness_excess);

    /**
     * The contact time of the collision of luding_epsilon() (force back to
     * zero) in units of sqrt(m/k1), m the effective mass:
     * (pi/2)(1 + (1 + a x)^{-1/2}) for x <= 1; for x > 1 the time
     * asin(1/x) to reach d_p on the k1 branch, then the kp branch about
     * d_p0 entered at s0 = d_p / (1 + a) with the speed sqrt(x^2 - 1)
     * (units of d_p and v_p) until it reaches d_p0:
     * (pi - atan2(s0 sqrt(1 + a), sqrt(x^2 - 1))) / sqrt(1 + a).
     */
    double
    luding_contact_time(double speed_over_plastic_speed,
                        double stiffness_excess);
  } // namespace Reference
} // namespace DiskImpact
