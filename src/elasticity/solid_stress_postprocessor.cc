#include "elasticity/solid_stress_postprocessor.h"

#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  SolidStressPostprocessor::SolidStressPostprocessor(
    const std::vector<Material> &materials)
  {
    for (const Material &material : materials)
      stiffness.push_back(material.stiffness_tensor<3>());
  }

  void
  SolidStressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<3> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    const auto  cell = inputs.template get_cell<3>();
    const auto &C    = stiffness.at(cell->material_id());
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
      {
        Tensor<2, 3> gradient;
        for (unsigned int d = 0; d < 3; ++d)
          gradient[d] = inputs.solution_gradients[q][d];
        const SymmetricTensor<2, 3> stress = C * symmetrize(gradient);
        unsigned int                k      = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            computed_quantities[q][k++] = stress[i][j];
        computed_quantities[q][k++] = std::sqrt(1.5) * deviator(stress).norm();
        computed_quantities[q][k]   = -trace(stress) / 3.;
      }
  }

  std::vector<std::string>
  SolidStressPostprocessor::get_names() const
  {
    std::vector<std::string> names(9, "stress");
    names.emplace_back("von_mises");
    names.emplace_back("pressure");
    return names;
  }

  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  SolidStressPostprocessor::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds(
      9, DataComponentInterpretation::component_is_part_of_tensor);
    kinds.push_back(DataComponentInterpretation::component_is_scalar);
    kinds.push_back(DataComponentInterpretation::component_is_scalar);
    return kinds;
  }

  UpdateFlags
  SolidStressPostprocessor::get_needed_update_flags() const
  {
    return update_gradients;
  }
} // namespace DiskImpact
