#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace DiskImpact
{
  class BodyGeometry;

  /**
   * A rigid, frictionless plane wall: a point on it and its unit normal,
   * pointing from the wall toward the disk. The gap of a point x is
   * g = (x - point) . normal; g < 0 is penetration.
   */
  struct RigidWall
  {
    dealii::Point<2>     point;
    dealii::Tensor<1, 2> normal;

    double
    gap(const dealii::Point<2> &x) const;
  };

  /// How the contact force of a time step is formed from the gaps at its
  /// start (g0) and end (g1).
  enum class ContactAverage
  {
    trapezoidal,      ///< (1 - w) p(g0) + w p(g1): Newmark, generalized-alpha
    discrete_gradient ///< -(E(g1) - E(g0)) / (g1 - g0): conserves energy
  };

  /// The two wall laws.
  enum class WallLawKind
  {
    penalty,     ///< p = k <-g>
    exponential, ///< p = p_c exp(-lambda g) for g < 0 (Gerl & Zippelius 1999,
                 ///< eq. 41)
    constraint   ///< g >= 0 exactly, the pressure a Lagrange multiplier
  };

  /**
   * The wall's pressure on the disk, along the wall normal, as a function of
   * the gap g of an edge point (g < 0: the point is beyond the plane where
   * the law starts to act), with its energy per unit boundary length:
   * - penalty: p = k <-g> (<.> the positive part), energy k <-g>^2 / 2;
   * - exponential: the smooth wall potential of Gerl & Zippelius 1999 (eq. 41),
   *   energy (E2 / lambda) exp(lambda x) per unit length with x the
   *   distance of the point beyond the wall plane and lambda = alpha / R,
   *   cut where its pressure E2 exp(lambda x) falls below p_c = 1e-16 E2:
   *   the law's plane g = 0 lies a distance ln(E2 / p_c) / lambda in front
   *   of the wall plane, p = p_c exp(-lambda g) and energy
   *   (p_c / lambda)(exp(-lambda g) - 1) for g < 0, both zero for g >= 0
   *   (the energy is continuous; the pressure jumps by p_c);
   * - constraint: no penetration, g >= 0, with a pressure that does no
   *   work (zero energy); its pressure is the complementarity problem's
   *   solution (ContactZone::constraint_system()), not a function of g.
   */
  struct WallLaw
  {
    WallLawKind kind = WallLawKind::penalty;
    /// Penalty: k [force / length^3].
    double stiffness = 0.;
    /// Exponential: lambda = alpha / R [1 / length] and p_c [pressure].
    double decay     = 0.;
    double threshold = 0.;

    double
    pressure(double gap) const;
    /// dp / dg: -k or -lambda p in penetration, 0 otherwise.
    double
    pressure_derivative(double gap) const;
    double
    energy(double gap) const;
    /// How far beyond the law's plane the pressure reaches the order of E2
    /// (the wall plane of the exponential law), 0 for the penalty.
    double
    reach() const;

    /**
     * The pressure averaged over a time step in which the gap goes from
     * @p g0 to @p g1, the discrete gradient of the energy:
     * p_bar = -(energy(g1) - energy(g0)) / (g1 - g0), so that
     * p_bar (g1 - g0) is exactly the energy released; the midpoint pressure
     * where g1 = g0.
     */
    double
    discrete_gradient_pressure(double g0, double g1) const;
    /// d p_bar / d g1.
    double
    discrete_gradient_derivative(double g0, double g1) const;
  };

  /**
   * Subsection "Contact": the wall, the law ('Law') and its constant: the
   * dimensionless penalty factor kappa of the penalty stiffness
   * k = kappa E2 / h_contact, or the stiffness alpha of the exponential
   * potential (Gerl & Zippelius 1999, eq. 41).
   */
  class ContactParameters
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    penalty_factor() const;
    void
    set_penalty_factor(double kappa);
    const RigidWall &
    wall() const;

    WallLawKind
    law_kind() const;

    /// The penalty law for in-plane modulus E2 and contact element size h.
    WallLaw
    penalty_law(double in_plane_young_modulus, double h_contact) const;

    /// The chosen law ('Law') for E2, contact element size h and radius R.
    WallLaw
    wall_law(double in_plane_young_modulus,
             double h_contact,
             double radius) const;

    /**
     * Check that the wall touches the undeformed disk (within
     * @p gap_tolerance R, positive gap allowed up to @p max_gap R) with the
     * disk on the side its normal points to, and that a half disk's wall is
     * perpendicular to the symmetry axis.
     */
    void
    check_wall(const BodyGeometry &geometry, double max_gap) const;

  private:
    double      kappa = 100.;
    WallLawKind kind  = WallLawKind::penalty;
    double      alpha = 100.;
    RigidWall   rigid_wall;
  };
} // namespace DiskImpact
