#pragma once

// What the tests of the three-dimensional and the plane-stress return
// mappings share: a point's constants, a plastic history and the consistent
// tangent against central differences of the stress.

#include "material/j2_return_mapping.h"

#include <catch2/catch.hpp>

/// Steel-like constants of a point in units of E: nu = 0.3, Y = 5e-3 E,
/// and Lamé's.
namespace point_constants
{
  constexpr double E = 1., nu = 0.3, Y = 5e-3;
  const double     mu     = E / (2. * (1. + nu));
  const double     lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
} // namespace point_constants

/// A plastic history: some plastic strain (trace free) and alpha.
inline DiskImpact::J2ReturnMapping::State
plastic_history()
{
  DiskImpact::J2ReturnMapping::State old;
  old.plastic_strain[0][0] = 1e-3, old.plastic_strain[1][1] = -4e-4;
  old.plastic_strain[2][2] = -6e-4, old.plastic_strain[0][1] = 2e-4;
  old.equivalent_plastic_strain = 1.2e-3;
  return old;
}

/// At @p strain from @p old, each strain component with indices below
/// @p n_directions (3: all six; 2: the in-plane ones) perturbed by +-h
/// (the off-diagonal ones symmetrically): the tangent's response within
/// 1e-6 of the stress's central difference.
inline void
check_tangent_by_differences(const DiskImpact::J2ReturnMapping        &law,
                             const dealii::SymmetricTensor<2, 3>      &strain,
                             const DiskImpact::J2ReturnMapping::State &old,
                             const unsigned int n_directions)
{
  const auto base = law.update(strain, old);
  REQUIRE(base.yielded);
  const double h = 1e-7;
  for (unsigned int k = 0; k < n_directions; ++k)
    for (unsigned int l = k; l < n_directions; ++l)
      {
        dealii::SymmetricTensor<2, 3> step;
        step[k][l]         = h;
        const auto plus    = law.update(strain + step, old);
        const auto minus   = law.update(strain - step, old);
        const auto numeric = (plus.stress - minus.stress) / (2. * h);
        const dealii::SymmetricTensor<2, 3> analytic = base.tangent * step / h;
        CHECK((numeric - analytic).norm() <= 1e-6 * analytic.norm());
      }
}
