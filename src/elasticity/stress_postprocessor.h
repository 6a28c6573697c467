#pragma once

#include "elasticity/material.h"

#include <deal.II/numerics/data_postprocessor.h>

namespace DiskImpact
{
  /// The Cauchy stress sigma = C : eps(u) of a displacement field, as a
  /// tensor field "stress" for ParaView.
  class StressPostprocessor : public dealii::DataPostprocessorTensor<2>
  {
  public:
    explicit StressPostprocessor(const Material &material);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;

  private:
    dealii::SymmetricTensor<4, 2> stiffness;
  };
} // namespace DiskImpact
