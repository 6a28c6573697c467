#pragma once

#include "elasticity/material.h"

#include <deal.II/numerics/data_postprocessor.h>

#include <string>
#include <vector>

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

  /**
   * The scalar stress measures one colours by, beside the tensor of
   * StressPostprocessor: "von_mises", "principal_stress_1",
   * "principal_stress_2" and "pressure".
   *
   * The von Mises stress and the pressure are those of the full 3D stress of
   * the plane model: sigma_zz = 0 in plane stress, and in plane strain
   * (eps_zz = 0) sigma_zz = nu (sigma_xx + sigma_yy) with the 3D Poisson
   * ratio nu = nu2 / (1 + nu2) (the inverse of seed 001, eq. 2). With
   * s = dev sigma (3D): von_mises = sqrt(3/2 s : s) = sqrt(3 J2) (von Mises'
   * equivalent stress, 1913), pressure = -tr(sigma) / 3. The principal
   * stresses are the eigenvalues sigma_1 >= sigma_2 of the in-plane stress,
   * from Mohr's circle (sigma_xx + sigma_yy) / 2 +-
   * sqrt(((sigma_xx - sigma_yy) / 2)^2 + sigma_xy^2); sigma_zz is the third.
   * Like "stress", the elastic stress C : eps (no Kelvin-Voigt viscous
   * part).
   */
  class StressScalarsPostprocessor : public dealii::DataPostprocessor<2>
  {
  public:
    explicit StressScalarsPostprocessor(const Material &material);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<
      dealii::DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    dealii::UpdateFlags
    get_needed_update_flags() const override;

    /// The 3D stress of an in-plane stress under the plane model.
    dealii::SymmetricTensor<2, 3>
    three_dimensional_stress(const dealii::SymmetricTensor<2, 2> &stress) const;

  private:
    dealii::SymmetricTensor<4, 2> stiffness;
    /// sigma_zz / (sigma_xx + sigma_yy): 0 (plane stress) or nu (plane strain).
    double out_of_plane_ratio;
  };
} // namespace DiskImpact
