// Material tensors: plane strain and plane stress against independent
// formulas, and the in-plane mapping of Gerl & Zippelius 1999, eq. 2.

#include "base/input_error.h"
#include "material/constitutive_law.h"
#include "material/material.h"

#include <deal.II/base/symmetric_tensor.h>

#include <catch2/catch.hpp>

using namespace DiskImpact;
using dealii::SymmetricTensor;

namespace
{
  /// Largest |C1_ijkl - C2_ijkl| relative to the largest |C1_ijkl|.
  double
  tensor_difference(const SymmetricTensor<4, 2> &a,
                    const SymmetricTensor<4, 2> &b)
  {
    double diff = 0., scale = 0.;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            {
              diff  = std::max(diff, std::abs(a[i][j][k][l] - b[i][j][k][l]));
              scale = std::max(scale, std::abs(a[i][j][k][l]));
            }
    return diff / scale;
  }
} // namespace

TEST_CASE("plane strain is the in-plane part of 3D elasticity", "[material]")
{
  // 3D Lame constants, independent of the in-plane route of the code.
  const double E = 2.5, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu     = E / (2 * (1 + nu));
  Material     m;
  m.set(PlaneModel::plane_strain, E, nu, 1.);
  const auto c = m.stiffness_tensor<2>();
  CHECK(c[0][0][0][0] == Approx(lambda + 2 * mu).epsilon(1e-14));
  CHECK(c[0][0][1][1] == Approx(lambda).epsilon(1e-14));
  CHECK(c[0][1][0][1] == Approx(mu).epsilon(1e-14));
}

TEST_CASE("plane stress stiffness inverts the plane-stress compliance",
          "[material]")
{
  // eps = (1/E) [[1, -nu, 0], [-nu, 1, 0], [0, 0, 2(1+nu)]] (Voigt, with
  // engineering shear): the code's C applied to it gives the identity.
  const double E = 3., nu = 0.33;
  Material     m;
  m.set(PlaneModel::plane_stress, E, nu, 1.);
  const auto            c = m.stiffness_tensor<2>();
  SymmetricTensor<2, 2> eps;
  eps[0][0]        = 1. / E;
  eps[1][1]        = -nu / E;
  const auto sigma = c * eps; // uniaxial stress sigma_xx = 1
  CHECK(sigma[0][0] == Approx(1.).epsilon(1e-14));
  CHECK(std::abs(sigma[1][1]) < 1e-14);
  SymmetricTensor<2, 2> shear;
  shear[0][1] = (1 + nu) / E; // tensor shear strain for sigma_xy = 1
  CHECK((c * shear)[0][1] == Approx(1.).epsilon(1e-14));
}

TEST_CASE("plane strain (E, nu) equals plane stress (E/(1-nu^2), nu/(1-nu))",
          "[material]")
{
  // nu up to 1/3, so that nu2 = nu / (1 - nu) <= 0.5 is a valid plane
  // stress value
  for (const double nu : {-0.5, 0., 0.2, 0.3, 1. / 3.})
    {
      CAPTURE(nu);
      Material strain, stress;
      strain.set(PlaneModel::plane_strain, 1.7, nu, 2.);
      stress.set(PlaneModel::plane_stress,
                 1.7 / (1 - nu * nu),
                 nu / (1 - nu),
                 2.);
      CHECK(tensor_difference(strain.stiffness_tensor<2>(),
                              stress.stiffness_tensor<2>()) < 1e-14);
      CHECK(strain.in_plane_young_modulus() ==
            Approx(stress.in_plane_young_modulus()));
      CHECK(strain.in_plane_poisson_ratio() ==
            Approx(stress.in_plane_poisson_ratio()));
      CHECK(strain.velocity_unit() == Approx(stress.velocity_unit()));
    }
}

TEST_CASE("Gerl & Zippelius' nu2 = 0.9 is plane strain with nu = 0.4737",
          "[material]")
{
  Material m;
  m.set(PlaneModel::plane_strain, 1., 0.9 / 1.9, 1.);
  CHECK(m.in_plane_poisson_ratio() == Approx(0.9).epsilon(1e-14));
}

TEST_CASE("wave speeds", "[material]")
{
  Material m;
  m.set(PlaneModel::plane_stress, 2., 0.25, 0.5);
  const double E2 = 2., nu2 = 0.25, rho = 0.5;
  // c_L^2 = E2 / ((1 - nu2^2) rho) (Gerl & Zippelius 1999, eq. 8), c_T^2 = mu /
  // rho.
  CHECK(m.longitudinal_wave_speed() ==
        Approx(std::sqrt(E2 / ((1 - nu2 * nu2) * rho))).epsilon(1e-14));
  CHECK(m.transverse_wave_speed() ==
        Approx(std::sqrt(E2 / (2 * (1 + nu2) * rho))).epsilon(1e-14));
  CHECK(m.velocity_unit() == Approx(2.).epsilon(1e-14));
}

TEST_CASE("invalid constants are rejected", "[material]")
{
  Material m;
  CHECK_THROWS_AS(m.set(PlaneModel::plane_strain, 1., 0.5, 1.), InputError);
  CHECK_THROWS_AS(m.set(PlaneModel::plane_strain, 1., -1., 1.), InputError);
  CHECK_THROWS_AS(m.set(PlaneModel::plane_stress, 1., 0.6, 1.), InputError);
  CHECK_THROWS_AS(m.set(PlaneModel::plane_stress, -1., 0.3, 1.), InputError);
  CHECK_THROWS_AS(m.set(PlaneModel::plane_stress, 1., 0.3, 0.), InputError);
  CHECK_THROWS_AS(m.set(PlaneModel::plane_stress, 1., 0.3, 1., -1.),
                  InputError);
  CHECK_NOTHROW(m.set(PlaneModel::plane_stress, 1., 0.5, 1.));
}

TEST_CASE("constitutive laws give the material's tangents", "[material]")
{
  // The elastic law's C is the material's, its D zero; Kelvin-Voigt adds
  // the material's D; neither changes its stiffness along a run.
  Material elastic, viscous;
  elastic.set(PlaneModel::plane_strain, 2., 0.3, 1.);
  viscous.set(PlaneModel::plane_stress, 2., 0.3, 1., 0.05);
  const QuadraturePointState state;
  const auto                 law = make_constitutive_law<2>(elastic);
  CHECK_FALSE(law->is_viscous());
  CHECK_FALSE(law->changes_stiffness());
  CHECK(tensor_difference(law->stiffness_tangent(state),
                          elastic.stiffness_tensor<2>()) == 0.);
  CHECK(law->damping_tangent(state).norm() == 0.);

  const auto kelvin_voigt = make_constitutive_law<2>(viscous);
  CHECK(kelvin_voigt->is_viscous());
  CHECK(dynamic_cast<const KelvinVoigtLaw<2> *>(kelvin_voigt.get()));
  CHECK(tensor_difference(kelvin_voigt->stiffness_tangent(state),
                          viscous.stiffness_tensor<2>()) == 0.);
  CHECK(tensor_difference(kelvin_voigt->damping_tangent(state),
                          viscous.damping_tensor<2>()) == 0.);
}
