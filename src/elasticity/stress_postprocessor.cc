#include "elasticity/stress_postprocessor.h"

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// sigma = C : eps with eps the symmetric part of grad u (row i the
    /// gradient of u_i).
    SymmetricTensor<2, 2>
    stress_from_gradient(const SymmetricTensor<4, 2>     &stiffness,
                         const std::vector<Tensor<1, 2>> &gradient)
    {
      SymmetricTensor<2, 2> strain;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          strain[i][j] = 0.5 * (gradient[i][j] + gradient[j][i]);
      return stiffness * strain;
    }
  } // namespace

  StressPostprocessor::StressPostprocessor(const Material &material)
      : DataPostprocessorTensor<2>("stress", update_gradients)
      , stiffness(material.stiffness_tensor())
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
          stress_from_gradient(stiffness, inputs.solution_gradients[q]);
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            computed_quantities[q][Tensor<2, 2>::component_to_unrolled_index(
              TableIndices<2>(i, j))] = stress[i][j];
      }
  }

  StressScalarsPostprocessor::StressScalarsPostprocessor(
    const Material &material)
      : stiffness(material.stiffness_tensor())
      , out_of_plane_ratio(material.plane_model() == PlaneModel::plane_strain ?
                             material.in_plane_poisson_ratio() /
                               (1. + material.in_plane_poisson_ratio()) :
                             0.)
  {
  }

  SymmetricTensor<2, 3>
  StressScalarsPostprocessor::three_dimensional_stress(
    const SymmetricTensor<2, 2> &stress) const
  {
    SymmetricTensor<2, 3> full;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        full[i][j] = stress[i][j];
    full[2][2] = out_of_plane_ratio * trace(stress);
    return full;
  }

  void
  StressScalarsPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
      {
        const SymmetricTensor<2, 2> stress =
          stress_from_gradient(stiffness, inputs.solution_gradients[q]);
        const SymmetricTensor<2, 3> full = three_dimensional_stress(stress);
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
      }
  }

  std::vector<std::string>
  StressScalarsPostprocessor::get_names() const
  {
    return {"von_mises",
            "principal_stress_1",
            "principal_stress_2",
            "pressure"};
  }

  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressScalarsPostprocessor::get_data_component_interpretation() const
  {
    return std::vector<
      DataComponentInterpretation::DataComponentInterpretation>(
      4, DataComponentInterpretation::component_is_scalar);
  }

  UpdateFlags
  StressScalarsPostprocessor::get_needed_update_flags() const
  {
    return update_gradients;
  }
} // namespace DiskImpact
