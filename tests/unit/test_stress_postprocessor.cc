// Stress output for ParaView: the tensor "stress" and the scalars von Mises,
// principal stresses and pressure on known strain states, hand-computed for
// plane stress and plane strain with the same in-plane constants (E2 = 1,
// nu2 = 1/3; plane strain: E = 15/16, nu = 1/4, Gerl & Zippelius 1999, eq. 2),
// checked against 3D Hooke's law and under rotation.

#include "elasticity/stress_postprocessor.h"
#include "material/material.h"

#include <deal.II/base/tensor.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace DiskImpact;
using dealii::Tensor;

namespace
{
  /// E2 = 1, nu2 = 1/3 as plane stress, and as plane strain (E = 15/16,
  /// nu = 1/4): the same in-plane stresses, different sigma_zz.
  Material
  material(const PlaneModel model)
  {
    Material m;
    if (model == PlaneModel::plane_stress)
      m.set(model, 1., 1. / 3., 1.);
    else
      m.set(model, 15. / 16., 0.25, 1.);
    return m;
  }

  /// A displacement gradient, row i the gradient of u_i.
  Tensor<2, 2>
  gradient(const double xx, const double xy, const double yx, const double yy)
  {
    Tensor<2, 2> g;
    g[0][0] = xx;
    g[0][1] = xy;
    g[1][0] = yx;
    g[1][1] = yy;
    return g;
  }

  /// The postprocessor's values at one point with displacement gradient g.
  dealii::Vector<double>
  evaluate(const dealii::DataPostprocessor<2> &postprocessor,
           const Tensor<2, 2>                 &g,
           const unsigned int                  n_components)
  {
    dealii::DataPostprocessorInputs::Vector<2> inputs;
    inputs.solution_gradients = {{g[0], g[1]}};
    std::vector<dealii::Vector<double>> values(
      1, dealii::Vector<double>(n_components));
    postprocessor.evaluate_vector_field(inputs, values);
    return values[0];
  }

  /// von_mises, principal_stress_1, principal_stress_2, pressure.
  struct Scalars
  {
    double von_mises, sigma_1, sigma_2, pressure;
  };

  Scalars
  scalars(const PlaneModel model, const Tensor<2, 2> &g)
  {
    const StressScalarsPostprocessor postprocessor(material(model));
    const auto                       v = evaluate(postprocessor, g, 4);
    return {v[0], v[1], v[2], v[3]};
  }

  /// sigma_ij from the tensor postprocessor "stress".
  double
  stress_component(const PlaneModel    model,
                   const Tensor<2, 2> &g,
                   const unsigned int  i,
                   const unsigned int  j)
  {
    const StressPostprocessor postprocessor(material(model));
    const auto                v = evaluate(postprocessor, g, 4);
    return v[Tensor<2, 2>::component_to_unrolled_index(
      dealii::TableIndices<2>(i, j))];
  }

  /// A hand-computed state: displacement gradient, in-plane stress and the
  /// scalars for plane stress and plane strain.
  struct KnownState
  {
    std::string  name;
    Tensor<2, 2> g;
    double       sxx, syy, sxy;
    double       sigma_1, sigma_2;
    double       von_mises_stress, pressure_stress; // plane stress
    double       von_mises_strain, pressure_strain; // plane strain
  };

  // E2 = 1, nu2 = 1/3: mu = E2 / (2 (1 + nu2)) = 3/8,
  // E2 / (1 - nu2) = 3/2; plane strain sigma_zz = (sxx + syy) / 4.
  const std::vector<KnownState> known_states = {
    // Uniaxial stress sigma_xx = 1: eps = diag(1/E2, -nu2/E2).
    // Plane strain: sigma = diag(1, 0, 1/4),
    // von Mises sqrt((1 + 1/16 + 9/16) / 2) = sqrt(13) / 4.
    {"uniaxial",
     gradient(1., 0., 0., -1. / 3.),
     1.,
     0.,
     0.,
     1.,
     0.,
     1.,
     -1. / 3.,
     std::sqrt(13.) / 4.,
     -5. / 12.},
    // Pure shear sigma_xy = 1 from a simple shear du_x/dy = gamma
    // (eps_xy = gamma / 2, sigma_xy = mu gamma, gamma = 8/3; the rotation
    // part carries no stress): principal +-1, von Mises sqrt(3), p = 0 in
    // both models (sigma_zz = 0).
    {"pure shear",
     gradient(0., 8. / 3., 0., 0.),
     0.,
     0.,
     1.,
     1.,
     -1.,
     std::sqrt(3.),
     0.,
     std::sqrt(3.),
     0.},
    // Equibiaxial sigma_xx = sigma_yy = 1: eps = (1 - nu2) / E2 I = 2/3 I.
    // Plane stress diag(1, 1, 0): von Mises 1, p = -2/3; plane strain
    // diag(1, 1, 1/2): von Mises 1/2, p = -5/6.
    {"equibiaxial",
     gradient(2. / 3., 0., 0., 2. / 3.),
     1.,
     1.,
     0.,
     1.,
     1.,
     1.,
     -2. / 3.,
     0.5,
     -5. / 6.},
  };

  /// R g R^T: the gradient of the same state in axes rotated by @p angle.
  Tensor<2, 2>
  rotated(const Tensor<2, 2> &g, const double angle)
  {
    Tensor<2, 2> r;
    r[0][0] = std::cos(angle);
    r[0][1] = -std::sin(angle);
    r[1][0] = std::sin(angle);
    r[1][1] = std::cos(angle);
    return r * g * transpose(r);
  }

  constexpr double tolerance = 1e-13;
} // namespace

TEST_CASE("stress postprocessor: hand-computed states, both plane models",
          "[stress postprocessor]")
{
  for (const auto &state : known_states)
    for (const PlaneModel model :
         {PlaneModel::plane_stress, PlaneModel::plane_strain})
      {
        const bool strain = model == PlaneModel::plane_strain;
        CAPTURE(state.name, strain);
        CHECK(stress_component(model, state.g, 0, 0) ==
              Approx(state.sxx).margin(tolerance));
        CHECK(stress_component(model, state.g, 1, 1) ==
              Approx(state.syy).margin(tolerance));
        CHECK(stress_component(model, state.g, 0, 1) ==
              Approx(state.sxy).margin(tolerance));
        CHECK(stress_component(model, state.g, 1, 0) ==
              Approx(state.sxy).margin(tolerance));
        const Scalars s = scalars(model, state.g);
        CHECK(s.sigma_1 == Approx(state.sigma_1).margin(tolerance));
        CHECK(s.sigma_2 == Approx(state.sigma_2).margin(tolerance));
        CHECK(s.von_mises ==
              Approx(strain ? state.von_mises_strain : state.von_mises_stress)
                .margin(tolerance));
        CHECK(s.pressure ==
              Approx(strain ? state.pressure_strain : state.pressure_stress)
                .margin(tolerance));
      }
}

TEST_CASE("stress postprocessor: plane strain is 3D Hooke's law with "
          "eps_zz = 0",
          "[stress postprocessor]")
{
  // 3D Lame constants of E = 15/16, nu = 1/4, independent of the in-plane
  // route of the code: lambda = E nu / ((1 + nu)(1 - 2 nu)) = 3/8,
  // mu = E / (2 (1 + nu)) = 3/8.
  const double E = 15. / 16., nu = 0.25;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu     = E / (2 * (1 + nu));
  for (const Tensor<2, 2> &g : {gradient(0.3, -0.7, 0.2, -0.45),
                                gradient(-1.1, 0.05, 0.4, 0.9),
                                gradient(0.2, 0., 0., 0.)})
    {
      CAPTURE(g);
      const double exx = g[0][0], eyy = g[1][1],
                   exy = 0.5 * (g[0][1] + g[1][0]);
      const double sxx = lambda * (exx + eyy) + 2 * mu * exx;
      const double syy = lambda * (exx + eyy) + 2 * mu * eyy;
      const double szz = lambda * (exx + eyy);
      const double sxy = 2 * mu * exy;
      const double von_mises =
        std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) +
                         (szz - sxx) * (szz - sxx)) +
                  3 * sxy * sxy);
      const double centre = 0.5 * (sxx + syy);
      const double radius =
        std::sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
      const Scalars s = scalars(PlaneModel::plane_strain, g);
      CHECK(s.von_mises == Approx(von_mises).epsilon(1e-13));
      CHECK(s.sigma_1 == Approx(centre + radius).epsilon(1e-13));
      CHECK(s.sigma_2 == Approx(centre - radius).epsilon(1e-13));
      CHECK(s.pressure == Approx(-(sxx + syy + szz) / 3.).epsilon(1e-13));
    }
}

TEST_CASE("stress postprocessor: scalars are invariant under rotation",
          "[stress postprocessor]")
{
  const std::vector<Tensor<2, 2>> gradients = {known_states[0].g,
                                               known_states[1].g,
                                               gradient(0.3, -0.7, 0.2, -0.45)};
  for (const PlaneModel model :
       {PlaneModel::plane_stress, PlaneModel::plane_strain})
    for (const auto &g : gradients)
      {
        const Scalars reference = scalars(model, g);
        for (const double angle : {0.3, 1.0, 2.5, -0.8})
          {
            CAPTURE(model == PlaneModel::plane_strain, g, angle);
            const Scalars s = scalars(model, rotated(g, angle));
            CHECK(s.von_mises == Approx(reference.von_mises).margin(tolerance));
            CHECK(s.sigma_1 == Approx(reference.sigma_1).margin(tolerance));
            CHECK(s.sigma_2 == Approx(reference.sigma_2).margin(tolerance));
            CHECK(s.pressure == Approx(reference.pressure).margin(tolerance));
          }
      }
  // The uniaxial state rotated by 30 degrees: sigma_xy != 0, yet the
  // principal stresses stay 1 and 0.
  const Scalars s =
    scalars(PlaneModel::plane_stress, rotated(known_states[0].g, M_PI / 6));
  CHECK(s.sigma_1 == Approx(1.).margin(tolerance));
  CHECK(s.sigma_2 == Approx(0.).margin(tolerance));
  CHECK(std::abs(stress_component(PlaneModel::plane_stress,
                                  rotated(known_states[0].g, M_PI / 6),
                                  0,
                                  1)) > 0.4);
}

TEST_CASE("stress postprocessor: nearly equal principal stresses",
          "[stress postprocessor]")
{
  // Equibiaxial sigma = 1 plus sigma_xy = 1e-9 (du_x/dy = 1e-9 / mu):
  // sigma_1 - sigma_2 = 2e-9 to full relative precision (the route through
  // tr^2 - 4 det would give 0 here).
  const Tensor<2, 2> g     = gradient(2. / 3., 1e-9 * 8. / 3., 0., 2. / 3.);
  const Scalars      s     = scalars(PlaneModel::plane_stress, g);
  const double       split = s.sigma_1 - s.sigma_2;
  CHECK(split == Approx(2e-9).epsilon(1e-6));
  CHECK(0.5 * (s.sigma_1 + s.sigma_2) == Approx(1.).epsilon(1e-14));
}

TEST_CASE("stress postprocessor: field names and kinds",
          "[stress postprocessor]")
{
  const StressScalarsPostprocessor scalars_out(
    material(PlaneModel::plane_stress));
  CHECK(scalars_out.get_names() ==
        std::vector<std::string>{
          "von_mises", "principal_stress_1", "principal_stress_2", "pressure"});
  for (const auto kind : scalars_out.get_data_component_interpretation())
    CHECK(kind == dealii::DataComponentInterpretation::component_is_scalar);
  CHECK((scalars_out.get_needed_update_flags() & dealii::update_gradients));
  const StressPostprocessor tensor_out(material(PlaneModel::plane_stress));
  CHECK(tensor_out.get_names() == std::vector<std::string>(4, "stress"));
}

TEST_CASE("sphere: hoop stress of a uniform expansion, on and off the axis",
          "[stress][axisymmetric]")
{
  // u = e (x - c) on the meridian is the 3D expansion eps = e 1: sigma =
  // 3 K e 1 with the bulk modulus K = E / (3 (1 - 2 nu)), the hoop stress
  // included; on the axis (r = 0) the hoop strain is the limit du_r/dr.
  const double E = 2., nu = 0.3, e = 1e-3, K = E / (3. * (1. - 2. * nu));
  Material     sphere;
  sphere.set(PlaneModel::axisymmetric, E, nu, 1.);
  const StressPostprocessor        tensor(sphere);
  const StressScalarsPostprocessor scalars(sphere);
  const dealii::Point<2>           centre(1., 0.);
  for (const dealii::Point<2> x :
       {dealii::Point<2>(0.3, 0.4), dealii::Point<2>(1.7, 0.)})
    {
      CAPTURE(x);
      dealii::DataPostprocessorInputs::Vector<2> inputs;
      inputs.evaluation_points  = {x};
      inputs.solution_values    = {dealii::Vector<double>(2)};
      inputs.solution_values[0] = dealii::Vector<double>(
        {e * (x[0] - centre[0]), e * (x[1] - centre[1])});
      const Tensor<2, 2> g      = gradient(e, 0., 0., e);
      inputs.solution_gradients = {{g[0], g[1]}};

      std::vector<dealii::Vector<double>> sigma(1, dealii::Vector<double>(4)),
        measures(1, dealii::Vector<double>(5));
      tensor.evaluate_vector_field(inputs, sigma);
      scalars.evaluate_vector_field(inputs, measures);
      CHECK(sigma[0][0] == Approx(3. * K * e).epsilon(1e-14));
      CHECK(sigma[0][3] == Approx(3. * K * e).epsilon(1e-14));
      CHECK(sigma[0][1] == Approx(0.).margin(1e-18));
      CHECK(measures[0][0] == Approx(0.).margin(1e-15));           // von Mises
      CHECK(measures[0][3] == Approx(-3. * K * e).epsilon(1e-14)); // pressure
      CHECK(measures[0][4] == Approx(3. * K * e).epsilon(1e-14));  // hoop
    }
  CHECK(scalars.get_names().back() == "hoop_stress");
  CHECK(scalars.get_data_component_interpretation().size() == 5);
}
