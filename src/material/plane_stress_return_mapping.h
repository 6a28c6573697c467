#pragma once

#include "material/j2_return_mapping.h"

namespace DiskImpact
{
  /**
   * J2ReturnMapping under plane stress (a thin disk), sigma_zz = 0. The
   * out-of-plane strain eps_zz is the unknown that makes it so: Newton's
   * method on the three-dimensional return mapping with its consistent
   * tangent's zz entry, from the elastic value, to rounding. The tangent
   * is the in-plane one with eps_zz condensed out, and the elastic stress
   * of a strain the plane-stress one, C_ps : eps in the plane: with the
   * plane-stress K and the plastic strain's in-plane part, sigma =
   * C_ps : (eps - eps_p) (eps_p's zz part is -tr of the in-plane part).
   * The strains are the plane's (eps_xz = eps_yz = 0); their zz entry is
   * ignored.
   */
  class PlaneStressReturnMapping : public J2ReturnMapping
  {
  public:
    PlaneStressReturnMapping(double lambda,
                             double mu,
                             double yield_stress,
                             double hardening_modulus);

    /// The stress (sigma_zz = 0) at the in-plane strain @p strain from
    /// the state @p old; the state's plastic strain has its zz part.
    Update
    update(const dealii::SymmetricTensor<2, 3> &strain,
           const State                         &old,
           bool with_tangent = true) const override;

    /// C_ps : eps in the plane, zero out of it.
    dealii::SymmetricTensor<2, 3>
    elastic_stress(const dealii::SymmetricTensor<2, 3> &strain) const override;

    /// C_ps in the plane, zero out of it.
    const dealii::SymmetricTensor<4, 3> &
    elastic_tangent() const override;

  private:
    double                        lambda, mu;
    dealii::SymmetricTensor<4, 3> plane_elastic;
  };
} // namespace DiskImpact
