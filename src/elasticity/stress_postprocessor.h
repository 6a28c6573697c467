#pragma once

#include "material/material.h"

#include <deal.II/numerics/data_postprocessor.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * The elastic stress of a displacement field at one output point: the
   * section's in-plane stress and the out-of-plane component sigma_zz (a
   * disk) or the hoop stress sigma_theta (a sphere, axisymmetric: the hoop
   * strain u_r / r, its limit du_r/dr on the axis, adds lambda eps_theta
   * to the in-plane normal stresses).
   */
  struct SectionStress
  {
    dealii::SymmetricTensor<2, 2> in_plane;
    double                        out_of_plane = 0.;

    /// The full 3D stress (out_of_plane as the third diagonal entry).
    dealii::SymmetricTensor<2, 3>
    three_dimensional() const;
  };

  /// The material's constants the stress output needs, set once: C, and
  /// the out-of-plane law (plane strain sigma_zz = nu tr sigma, plane
  /// stress 0, or the sphere's hoop stress).
  class SectionStressModel
  {
  public:
    explicit SectionStressModel(const Material &material);

    /// The stress at output point @p q of @p inputs.
    SectionStress
    evaluate(const dealii::DataPostprocessorInputs::Vector<2> &inputs,
             unsigned int                                      q) const;

    /// Gradients; on a sphere also values and points (the hoop strain).
    dealii::UpdateFlags
    needed_update_flags() const;

    /// Whether the out-of-plane stress is a sphere's hoop stress.
    bool
    is_axisymmetric() const;

  private:
    dealii::SymmetricTensor<4, 2> stiffness;
    bool                          axisymmetric;
    double                        lambda;
    double                        mu;
    /// sigma_zz / (sigma_xx + sigma_yy) of a disk: 0 (plane stress) or nu
    /// (plane strain).
    double out_of_plane_ratio;
  };

  /// The model of each material, and the one of the cell @p inputs are on.
  std::vector<SectionStressModel>
  section_stress_models(const std::vector<Material> &materials);
  const SectionStressModel &
  section_stress_model_of(
    const std::vector<SectionStressModel>            &models,
    const dealii::DataPostprocessorInputs::Vector<2> &inputs);

  /// The Cauchy stress sigma = C : eps(u) of a displacement field, as a
  /// tensor field "stress" for ParaView (the meridian's components on a
  /// sphere).
  class StressPostprocessor : public dealii::DataPostprocessorTensor<2>
  {
  public:
    explicit StressPostprocessor(const Material &material);
    /// Cells with material id i take @p materials[i] (two bodies).
    explicit StressPostprocessor(const std::vector<Material> &materials);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;

  private:
    std::vector<SectionStressModel> models;
  };

  /**
   * The scalar stress measures one colours by, beside the tensor of
   * StressPostprocessor: "von_mises", "principal_stress_1",
   * "principal_stress_2" and "pressure".
   *
   * The von Mises stress and the pressure are those of the full 3D stress of
   * the plane model: sigma_zz = 0 in plane stress, and in plane strain
   * (eps_zz = 0) sigma_zz = nu (sigma_xx + sigma_yy) with the 3D Poisson
   * ratio nu = nu2 / (1 + nu2) (the inverse of Gerl & Zippelius 1999, eq. 2).
   * With s = dev sigma (3D): von_mises = sqrt(3/2 s : s) = sqrt(3 J2) (von
   * Mises' equivalent stress, 1913), pressure = -tr(sigma) / 3. The principal
   * stresses are the eigenvalues sigma_1 >= sigma_2 of the in-plane stress,
   * from Mohr's circle (sigma_xx + sigma_yy) / 2 +-
   * sqrt(((sigma_xx - sigma_yy) / 2)^2 + sigma_xy^2); sigma_zz is the third.
   * Like "stress", the elastic stress C : eps (no Kelvin-Voigt viscous
   * part). On a sphere the third principal stress is the hoop stress
   * (SectionStress), written as a fifth field "hoop_stress".
   */
  class StressScalarsPostprocessor : public dealii::DataPostprocessor<2>
  {
  public:
    explicit StressScalarsPostprocessor(const Material &material);
    /// Cells with material id i take @p materials[i] (two bodies).
    explicit StressScalarsPostprocessor(const std::vector<Material> &materials);

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

  private:
    std::vector<SectionStressModel> models;
  };
} // namespace DiskImpact
