#pragma once

#include "material/material.h"

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * The elastic stress sigma = C : eps(u) of a displacement field in a
   * three-dimensional body, for ParaView: the tensor "stress" and the
   * scalars "von_mises" (sqrt(3/2) |dev sigma|) and "pressure"
   * (-tr sigma / 3), as the plane models write them. Cells with material
   * id i take the i-th material.
   */
  class SolidStressPostprocessor : public dealii::DataPostprocessor<3>
  {
  public:
    explicit SolidStressPostprocessor(const std::vector<Material> &materials);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<3> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<
      dealii::DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    dealii::UpdateFlags
    get_needed_update_flags() const override;

  private:
    std::vector<dealii::SymmetricTensor<4, 3>> stiffness;
  };
} // namespace DiskImpact
