#include "material/plane_stress_return_mapping.h"

#include "base/run_error.h"

#include <cmath>
#include <string>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// @p c with eps_zz condensed out: C_ijkl - C_ijzz C_zzkl / C_zzzz in
    /// the plane (sigma_zz = 0 at any in-plane strain), zero elsewhere.
    SymmetricTensor<4, 3>
    condensed(const SymmetricTensor<4, 3> &c)
    {
      SymmetricTensor<4, 3> block;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = k; l < 2; ++l)
              block[i][j][k][l] =
                c[i][j][k][l] - c[i][j][2][2] * c[2][2][k][l] / c[2][2][2][2];
      return block;
    }
  } // namespace

  PlaneStressReturnMapping::PlaneStressReturnMapping(
    const double lambda,
    const double mu,
    const double yield_stress,
    const double hardening_modulus)
      : J2ReturnMapping(lambda, mu, yield_stress, hardening_modulus)
      , lambda(lambda)
      , mu(mu)
      , plane_elastic(condensed(J2ReturnMapping::elastic_tangent()))
  {
  }

  J2ReturnMapping::Update
  PlaneStressReturnMapping::update(const SymmetricTensor<2, 3> &strain,
                                   const State                 &old,
                                   const bool with_tangent) const
  {
    // The elastic eps_zz: sigma_zz = lambda tr(eps - eps_p) + 2 mu (eps_zz -
    // eps_p,zz) = 0 with tr eps_p = 0. Exact if the point stays elastic.
    SymmetricTensor<2, 3> eps = strain;
    eps[2][2]                 = (2. * mu * old.plastic_strain[2][2] -
                 lambda * (strain[0][0] + strain[1][1])) /
                (lambda + 2. * mu);
    Update result = J2ReturnMapping::update(eps, old, true);
    // Newton on sigma_zz(eps_zz), piecewise smooth: quadratic once on the
    // yielding branch.
    const double scale      = yield_stress() + result.stress.norm();
    unsigned int iterations = 0;
    while (std::abs(result.stress[2][2]) > 1e-14 * scale)
      {
        if (++iterations > 50)
          throw RunError("plane stress return mapping: sigma_zz did not "
                         "vanish in 50 Newton iterations (|sigma_zz| = " +
                         std::to_string(std::abs(result.stress[2][2])) + ")");
        eps[2][2] -= result.stress[2][2] / result.tangent[2][2][2][2];
        result = J2ReturnMapping::update(eps, old, true);
      }
    result.stress[2][2] = 0.;
    result.tangent =
      with_tangent ? condensed(result.tangent) : SymmetricTensor<4, 3>();
    return result;
  }

  SymmetricTensor<2, 3>
  PlaneStressReturnMapping::elastic_stress(
    const SymmetricTensor<2, 3> &strain) const
  {
    SymmetricTensor<2, 3> plane = strain;
    plane[2][2]                 = 0.;
    return plane_elastic * plane;
  }

  const SymmetricTensor<4, 3> &
  PlaneStressReturnMapping::elastic_tangent() const
  {
    return plane_elastic;
  }
} // namespace DiskImpact
