#include "material/material.h"

#include <deal.II/base/symmetric_tensor.h>

#include <catch2/catch.hpp>

using namespace DiskImpact;
using namespace dealii;

TEST_CASE("Kelvin-Voigt damping tensor", "[material][damping]")
{
  Material material;
  material.set(PlaneModel::plane_stress, 2., 0.25, 1., 0.1);
  SymmetricTensor<2, 2> shear, dilatation;
  shear[0][1]      = 0.5;
  dilatation[0][0] = dilatation[1][1] = 1.;

  // tau C alone
  CHECK(material.is_viscous());
  const auto c = material.stiffness_tensor<2>();
  CHECK((material.damping_tensor<2>() * shear - 0.1 * (c * shear)).norm() ==
        Approx(0.).margin(1e-15));

  // shear viscosity: 2 eta_s dev(eps_dot), nothing for a dilatation
  material.set(PlaneModel::plane_stress, 2., 0.25, 1., 0.);
  material.set_viscosities(0.3, 0.);
  CHECK((material.damping_tensor<2>() * shear - 0.6 * shear).norm() ==
        Approx(0.).margin(1e-15));
  CHECK((material.damping_tensor<2>() * dilatation).norm() ==
        Approx(0.).margin(1e-15));

  // bulk viscosity: eta_b tr(eps_dot) 1, nothing for a pure shear
  material.set_viscosities(0., 0.7);
  CHECK((material.damping_tensor<2>() * dilatation - 1.4 * dilatation).norm() ==
        Approx(0.).margin(1e-15));
  CHECK((material.damping_tensor<2>() * shear).norm() ==
        Approx(0.).margin(1e-15));

  material.set_viscosities(0., 0.);
  CHECK_FALSE(material.is_viscous());
  CHECK_THROWS(material.set_viscosities(-1., 0.));
}
