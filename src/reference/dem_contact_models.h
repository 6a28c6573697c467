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
     * The viscoelastic sphere (Brilliantov et al., seed 003) in LAMMPS'
     * 'pair_style granular' ('hertz/material E eta_n0 nu ... damping
     * viscoelastic'): LAMMPS's damping force eta_n0 a m_eff d' with the
     * contact radius a = sqrt(R_eff d) equals A dF/dt = 2 A E_eff a d' of
     * seed 003 for eta_n0 = 2 A E_eff / m_eff.
     */
    double
    lammps_viscoelastic_damping(double dissipative_constant,
                                double effective_modulus,
                                double effective_mass);
  } // namespace Reference
} // namespace DiskImpact
