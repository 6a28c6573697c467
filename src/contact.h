#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace DiskImpact
{
  class DiskGeometry;

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

  /**
   * Penalty contact law: the wall pushes on the disk with the pressure
   * p = k <-g> (<.> the positive part) along the wall normal; its energy per
   * unit boundary length is k <-g>^2 / 2.
   */
  struct PenaltyLaw
  {
    double stiffness = 0.;

    double
    pressure(double gap) const;
    /// dp / dg: -k in penetration, 0 otherwise.
    double
    pressure_derivative(double gap) const;
    double
    energy(double gap) const;

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
   * Subsection "Contact": the wall and the dimensionless penalty factor
   * kappa of the penalty stiffness k = kappa E2 / h_contact.
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

    /// The penalty law for in-plane modulus E2 and contact element size h.
    PenaltyLaw
    penalty_law(double in_plane_young_modulus, double h_contact) const;

    /**
     * Check that the wall touches the undeformed disk (within
     * @p gap_tolerance R, positive gap allowed up to @p max_gap R) with the
     * disk on the side its normal points to, and that a half disk's wall is
     * perpendicular to the symmetry axis.
     */
    void
    check_wall(const DiskGeometry &geometry, double max_gap) const;

  private:
    double    kappa = 100.;
    RigidWall rigid_wall;
  };
} // namespace DiskImpact
