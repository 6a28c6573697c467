#pragma once

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * A round body's velocities in an oblique impact on the wall: the
     * normal velocity toward the wall v_n > 0, the tangential velocity v_t
     * of its centre along the wall, and its spin omega, counted positive
     * when it moves the contact point along +t. The contact point slides
     * at s = v_t + R omega.
     */
    struct ObliqueVelocities
    {
      double normal     = 0.;
      double tangential = 0.;
      double spin       = 0.;
    };

    /// After an oblique impact of rigid-body impulse theory.
    struct RigidObliqueImpact
    {
      ObliqueVelocities after;
      /// The contact point's tangential velocity s before and after.
      double slip_before = 0.;
      double slip_after  = 0.;
      /// The normal impulse J_n and the friction impulse J_t (along t).
      double normal_impulse     = 0.;
      double tangential_impulse = 0.;
      /// mu times the integral of |s| over the normal impulse.
      double friction_work = 0.;
      /// Whether the contact point stops before the impact ends.
      bool sticks = false;
    };

    /**
     * The oblique impact of a round rigid body of mass @p mass, radius
     * @p radius and moment of inertia k m R^2 (@p inertia_factor k: 1/2
     * a disk, 2/5 a sphere) on a rigid wall with Coulomb friction
     * @p friction (mu), given the normal restitution @p normal_restitution
     * e_n (the elastic body's, computed).
     *
     * The normal impulse J_n = m (1 + e_n) v_n acts through the centre.
     * The friction impulse J_t acts at the contact point against the slip
     * s = v_t + R omega: dv_t = dJ_t / m, d omega = R dJ_t / (k m R^2),
     * so ds = (1 + 1/k) dJ_t / m, and |dJ_t| = mu dJ_n while the point
     * slides. Gross sliding lasts the whole impact if
     * mu (1 + e_n) v_n (1 + 1/k) < |s|: then J_t = -mu J_n sign(s), and
     * the tangential restitution of the centre of mass is
     * v_t' / v_t = 1 - mu (1 + e_n) v_n / v_t sign(s). Otherwise the point
     * stops (and stays stopped in this theory): J_t = -m s / (1 + 1/k).
     * The angular momentum about the contact point, k m R^2 omega - m R v_t,
     * is unchanged either way. The friction work mu int |s| dJ_n is
     * mu J_n (|s| + |s'|) / 2 while sliding (s is linear in J_n), and the
     * same over the impulse before the stop when the point sticks.
     */
    RigidObliqueImpact
    rigid_oblique_impact(double                   mass,
                         double                   radius,
                         double                   inertia_factor,
                         double                   friction,
                         double                   normal_restitution,
                         const ObliqueVelocities &before);
  } // namespace Reference
} // namespace DiskImpact
