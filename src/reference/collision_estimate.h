#pragma once

#include "reference/two_body_contact.h"

namespace DiskImpact
{
  /// What the 1-DOF log-law model expects of a collision: the basis of the
  /// time step and of the mesh near the contact.
  struct CollisionEstimate
  {
    double contact_time            = 0.; ///< [time], for the time step
    double largest_load            = 0.; ///< P / (pi E2 R) at the largest force
    double largest_compression     = 0.; ///< centre-of-mass approach [length]
    double one_dof_contact_time    = 0.; ///< [R / c]; NaN beyond the log law
    double one_dof_delta_max       = 0.; ///< [R]; NaN beyond the log law
    double one_dof_epsilon         = 1.; ///< with viscosity; NaN beyond it
    double one_dof_epsilon_overlap = 1.; ///< ended at zero overlap
    /// with the Kelvin-Voigt unloading law (kelvin_voigt_unloading_force())
    double one_dof_epsilon_unloading = 1.;
  };

  namespace Reference
  {
    /// A body hitting the rigid wall, as the 1-DOF model sees it.
    struct WallCollision
    {
      bool   sphere = false;
      double mass   = 0.; ///< of the modelled body (whole disk or sphere)
      double speed  = 0.; ///< v_i / c
      double velocity_unit   = 1.; ///< c
      double modulus         = 1.; ///< E2 (disk) or E* (sphere)
      double radius          = 1.;
      double law_constant    = 0.; ///< the wall law's C (disk) or D (sphere)
      double relaxation_time = 0.; ///< Kelvin-Voigt tau (0: elastic)
    };

    /**
     * The 1-DOF collision of @p body with the wall (the log law of the disk,
     * Hertz's law with the finite-size constant of the sphere), with
     * Kelvin-Voigt viscosity m xi'' + F + tau xi' F' = 0 (Schwager 2007,
     * eq. 4; Ramírez et al. 1999, eq. 5, with A = tau). Beyond the disk's
     * log law: no 1-DOF values (NaN), the contact time and load of Gerl &
     * Zippelius' eq. 61.
     */
    CollisionEstimate
    estimate_wall_collision(const WallCollision &body);

    /// Two bodies colliding, as the 1-DOF model of their relative motion
    /// sees them (docs/theory/two-body-law.md).
    struct PairCollision
    {
      bool        sphere        = false;
      double      mass          = 0.; ///< the body's
      double      partner_mass  = 0.;
      double      speed         = 0.; ///< relative v_i / c
      double      velocity_unit = 1.; ///< c of the body
      double      radius        = 1.; ///< the body's R, the length unit
      ContactBody body, partner;
      double      relaxation_time = 0., partner_relaxation_time = 0.;
    };

    /// The 1-DOF collision of the reduced mass on the pair's law, each
    /// body with its own constant; with viscosity only for equal
    /// relaxation times (NaN otherwise).
    CollisionEstimate
    estimate_pair_collision(const PairCollision &pair);
  } // namespace Reference
} // namespace DiskImpact
