#include "elasticity/stress_postprocessor.h"

namespace DiskImpact
{
  using namespace dealii;

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
        SymmetricTensor<2, 2> strain;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = i; j < 2; ++j)
            strain[i][j] = 0.5 * (inputs.solution_gradients[q][i][j] +
                                  inputs.solution_gradients[q][j][i]);
        const SymmetricTensor<2, 2> stress = stiffness * strain;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            computed_quantities[q][Tensor<2, 2>::component_to_unrolled_index(
              TableIndices<2>(i, j))] = stress[i][j];
      }
  }
} // namespace DiskImpact
