#pragma once

#include <memory>

namespace DiskImpact::Reference
{
  /**
   * The tangential displacement of a body pressed on a rigid wall by P and
   * pulled along it by Q = q mu P with Coulomb friction, without the
   * coupling of normal and tangential tractions (Cattaneo 1938, Mindlin
   * 1949; docs/theory/tangential-compliance.md): the stick zone shrinks
   * from the contact's edge as q grows.
   */
  class TangentialCompliance
  {
  public:
    virtual ~TangentialCompliance() = default;

    /// The displacement along the wall of the body's rigid motion at the
    /// contact point (the centre's less R times the rotation), over R, at
    /// Q = @p q mu P, for @p friction_load = mu P / (E2 R^(dim - 2)) (E2
    /// = E* for a sphere), the contact's half-width or radius @p a (over
    /// R) and the Poisson ratio @p nu (in-plane for a disk).
    virtual double
    displacement(double q, double friction_load, double a, double nu) const = 0;

    /// The stick zone's half-width or radius over a at Q = @p q mu P.
    virtual double
    stick_radius(double q) const = 0;
  };

  /**
   * The disk's initial tangential stiffness dQ/d delta_c over its normal
   * stiffness dP/d delta_com at the contact half-width @p a (over R), for the
   * in-plane Poisson ratio @p nu2: both laws are logarithmic,
   * (2 ln(4/a) + C_com - 1) / (2 ln(4/a) + C_I - 1)
   * (docs/theory/tangential-compliance.md); the disk's counterpart of
   * Mindlin's 2(1 - nu)/(2 - nu).
   */
  double
  disk_tangential_stiffness_ratio(double a, double nu2);

  /// C_I of the disk's rigid motion at the contact point, the centre's
  /// displacement less R theta_I (docs/theory/tangential-compliance.md).
  double
  cattaneo_constant(double nu2);

  /// Mindlin's sphere (@p sphere) or Cattaneo's disk.
  std::unique_ptr<TangentialCompliance>
  tangential_compliance(bool sphere);
} // namespace DiskImpact::Reference
