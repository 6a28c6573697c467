#pragma once

#include <deal.II/base/symmetric_tensor.h>

namespace DiskImpact
{
  /**
   * Von Mises (J2) plasticity with linear isotropic hardening at one
   * point, small strains, backward Euler: the radial return and its
   * consistent tangent (Simo & Hughes, Computational Inelasticity, 1998,
   * box 3.2). The strains are three-dimensional: plane strain, the
   * axisymmetric meridian (with its hoop strain) and 3D bodies embed theirs.
   *
   * Yield function f = |dev sigma| - sqrt(2/3) (Y + H alpha), alpha the
   * equivalent plastic strain; H = 0 is perfect plasticity.
   * PlaneStressReturnMapping adds the condition sigma_zz = 0.
   */
  class J2ReturnMapping
  {
  public:
    /// The plastic strain and alpha at one point.
    struct State
    {
      dealii::SymmetricTensor<2, 3> plastic_strain;
      double                        equivalent_plastic_strain = 0.;
    };

    /// The result of one step from a converged state.
    struct Update
    {
      dealii::SymmetricTensor<2, 3> stress;
      /// d sigma / d eps, consistent with the return (C where elastic).
      dealii::SymmetricTensor<4, 3> tangent;
      State                         state;
      bool                          yielded = false;
      /// sigma_{n+1} : (eps^p_{n+1} - eps^p_n), the step's plastic work
      /// (dissipation and the energy stored by hardening).
      double plastic_work = 0.;
    };

    /// Lamé's lambda and mu, the yield stress Y > 0 and the hardening
    /// modulus H >= 0.
    J2ReturnMapping(double lambda,
                    double mu,
                    double yield_stress,
                    double hardening_modulus);
    virtual ~J2ReturnMapping() = default;

    /// The stress at the total strain @p strain from the state @p old;
    /// the tangent only if @p with_tangent (else left zero).
    virtual Update
    update(const dealii::SymmetricTensor<2, 3> &strain,
           const State                         &old,
           bool                                 with_tangent = true) const;

    /// C : eps, the elastic stress of a strain.
    virtual dealii::SymmetricTensor<2, 3>
    elastic_stress(const dealii::SymmetricTensor<2, 3> &strain) const;

    /// C, the tangent where the point responds elastically.
    virtual const dealii::SymmetricTensor<4, 3> &
    elastic_tangent() const;

    double
    yield_stress() const;
    double
    hardening_modulus() const;

  private:
    double                        mu, yield, hardening;
    dealii::SymmetricTensor<4, 3> elastic;
  };
} // namespace DiskImpact
