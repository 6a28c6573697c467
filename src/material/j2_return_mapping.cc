#include "material/j2_return_mapping.h"

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  using namespace dealii;

  J2ReturnMapping::J2ReturnMapping(const double lambda,
                                   const double mu,
                                   const double yield_stress,
                                   const double hardening_modulus)
      : mu(mu)
      , yield(yield_stress)
      , hardening(hardening_modulus)
      , elastic(lambda * outer_product(unit_symmetric_tensor<3>(),
                                       unit_symmetric_tensor<3>()) +
                2. * mu * identity_tensor<3>())
  {
    if (!(yield_stress > 0.) || !(hardening_modulus >= 0.) || !(mu > 0.))
      throw std::invalid_argument("J2ReturnMapping: needs Y > 0, H >= 0 "
                                  "and mu > 0");
  }

  J2ReturnMapping::Update
  J2ReturnMapping::update(const SymmetricTensor<2, 3> &strain,
                          const State                 &old,
                          const bool                   with_tangent) const
  {
    Update result;
    result.state  = old;
    result.stress = elastic * (strain - old.plastic_strain);
    if (with_tangent)
      result.tangent = elastic;
    const SymmetricTensor<2, 3> trial_deviator = deviator(result.stress);
    const double                trial_norm     = trial_deviator.norm();
    const double                radius =
      std::sqrt(2. / 3.) * (yield + hardening * old.equivalent_plastic_strain);
    const double f = trial_norm - radius;
    if (f <= 0.)
      return result;

    // Radial return: the deviator shrinks along n by 2 mu dgamma.
    const double                denominator = 2. * mu + 2. / 3. * hardening;
    const double                dgamma      = f / denominator;
    const SymmetricTensor<2, 3> n           = trial_deviator / trial_norm;
    result.yielded                          = true;
    result.stress -= 2. * mu * dgamma * n;
    result.state.plastic_strain += dgamma * n;
    result.state.equivalent_plastic_strain += std::sqrt(2. / 3.) * dgamma;
    // sigma_{n+1} : dgamma n = dgamma |dev sigma_{n+1}|.
    result.plastic_work = dgamma * (trial_norm - 2. * mu * dgamma);
    if (!with_tangent)
      return result;

    // C - (2 mu)^2 / (2 mu + 2H/3) n (x) n
    //   - (2 mu)^2 dgamma / |s_trial| (I_dev - n (x) n).
    const SymmetricTensor<4, 3> n_n = outer_product(n, n);
    const SymmetricTensor<4, 3> deviatoric_identity =
      identity_tensor<3>() -
      1. / 3. *
        outer_product(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>());
    const double scale = 4. * mu * mu;
    result.tangent -= scale / denominator * n_n +
                      scale * dgamma / trial_norm * (deviatoric_identity - n_n);
    return result;
  }

  SymmetricTensor<2, 3>
  J2ReturnMapping::elastic_stress(const SymmetricTensor<2, 3> &strain) const
  {
    return elastic * strain;
  }

  const SymmetricTensor<4, 3> &
  J2ReturnMapping::elastic_tangent() const
  {
    return elastic;
  }

  double
  J2ReturnMapping::yield_stress() const
  {
    return yield;
  }

  double
  J2ReturnMapping::hardening_modulus() const
  {
    return hardening;
  }
} // namespace DiskImpact
