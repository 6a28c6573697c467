#include "elasticity/stress_postprocessor.h"

#include "elasticity/section.h"

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// eps, the symmetric part of grad u (row i the gradient of u_i).
    SymmetricTensor<2, 2>
    strain_from_gradient(const std::vector<Tensor<1, 2>> &gradient)
    {
      SymmetricTensor<2, 2> strain;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          strain[i][j] = 0.5 * (gradient[i][j] + gradient[j][i]);
      return strain;
    }
  } // namespace

  SectionStressModel::SectionStressModel(const Material &material)
      : stiffness(material.stiffness_tensor<2>())
      , axisymmetric(material.plane_model() == PlaneModel::axisymmetric)
      , lambda(material.lame_lambda())
      , mu(material.shear_modulus())
      , out_of_plane_ratio(material.plane_model() == PlaneModel::plane_strain ?
                             material.in_plane_poisson_ratio() /
                               (1. + material.in_plane_poisson_ratio()) :
                             0.)
  {
  }

  SectionStress
  SectionStressModel::evaluate(const DataPostprocessorInputs::Vector<2> &inputs,
                               const unsigned int q) const
  {
    const SymmetricTensor<2, 2> strain =
      strain_from_gradient(inputs.solution_gradients[q]);
    SectionStress stress;
    stress.in_plane = stiffness * strain;
    if (!axisymmetric)
      {
        stress.out_of_plane = out_of_plane_ratio * trace(stress.in_plane);
        return stress;
      }
    // eps_theta = u_r / r, and du_r/dr where r = 0 (u_r = 0 there).
    const double r = inputs.evaluation_points[q][1];
    const double hoop =
      std::abs(r) > 1e-12 * inputs.evaluation_points[q].norm() ?
        inputs.solution_values[q][1] / r :
        inputs.solution_gradients[q][1][1];
    stress.in_plane += lambda * hoop * unit_symmetric_tensor<2>();
    stress.out_of_plane = lambda * (trace(strain) + hoop) + 2. * mu * hoop;
    return stress;
  }

  UpdateFlags
  SectionStressModel::needed_update_flags() const
  {
    return axisymmetric ?
             update_values | update_gradients | update_quadrature_points :
             update_gradients;
  }

  bool
  SectionStressModel::is_axisymmetric() const
  {
    return axisymmetric;
  }

  SymmetricTensor<2, 3>
  SectionStress::three_dimensional() const
  {
    return DiskImpact::three_dimensional(in_plane, out_of_plane);
  }

  std::vector<SectionStressModel>
  section_stress_models(const std::vector<Material> &materials)
  {
    return {materials.begin(), materials.end()};
  }

  const SectionStressModel &
  section_stress_model_of(const std::vector<SectionStressModel>    &models,
                          const DataPostprocessorInputs::Vector<2> &inputs)
  {
    if (models.size() == 1)
      return models[0];
    const auto cell = inputs.template get_cell<2>();
    AssertIndexRange(cell->material_id(), models.size());
    return models[cell->material_id()];
  }

  StressPostprocessor::StressPostprocessor(const Material &material)
      : StressPostprocessor(std::vector<Material>{material})
  {
  }

  StressPostprocessor::StressPostprocessor(
    const std::vector<Material> &materials)
      : DataPostprocessorTensor<2>(
          "stress",
          SectionStressModel(materials.at(0)).needed_update_flags())
      , models(section_stress_models(materials))
  {
  }

  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
      {
        const SymmetricTensor<2, 2> stress =
          section_stress_model_of(models, inputs).evaluate(inputs, q).in_plane;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            computed_quantities[q][Tensor<2, 2>::component_to_unrolled_index(
              TableIndices<2>(i, j))] = stress[i][j];
      }
  }

  StressScalarsPostprocessor::StressScalarsPostprocessor(
    const Material &material)
      : StressScalarsPostprocessor(std::vector<Material>{material})
  {
  }

  StressScalarsPostprocessor::StressScalarsPostprocessor(
    const std::vector<Material> &materials)
      : models(section_stress_models(materials))
  {
  }

  void
  StressScalarsPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
      {
        const SectionStress section =
          section_stress_model_of(models, inputs).evaluate(inputs, q);
        const SymmetricTensor<2, 2> &stress = section.in_plane;
        const SymmetricTensor<2, 3>  full   = section.three_dimensional();
        // Mohr's circle: centre and radius. deal.II's eigenvalues() goes
        // through tr^2 - 4 det, which loses half the digits of sigma_1 -
        // sigma_2 when the two are close (its documented warning).
        const double centre = 0.5 * trace(stress);
        const double radius =
          std::hypot(0.5 * (stress[0][0] - stress[1][1]), stress[0][1]);
        computed_quantities[q][0] = std::sqrt(1.5) * deviator(full).norm();
        computed_quantities[q][1] = centre + radius;
        computed_quantities[q][2] = centre - radius;
        computed_quantities[q][3] = -trace(full) / 3.;
        if (models[0].is_axisymmetric())
          computed_quantities[q][4] = section.out_of_plane;
      }
  }

  std::vector<std::string>
  StressScalarsPostprocessor::get_names() const
  {
    std::vector<std::string> names = {"von_mises",
                                      "principal_stress_1",
                                      "principal_stress_2",
                                      "pressure"};
    if (models[0].is_axisymmetric())
      names.emplace_back("hoop_stress");
    return names;
  }

  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressScalarsPostprocessor::get_data_component_interpretation() const
  {
    return std::vector<
      DataComponentInterpretation::DataComponentInterpretation>(
      get_names().size(), DataComponentInterpretation::component_is_scalar);
  }

  UpdateFlags
  StressScalarsPostprocessor::get_needed_update_flags() const
  {
    return models[0].needed_update_flags();
  }
} // namespace DiskImpact
