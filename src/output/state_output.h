#pragma once

#include "base/unit_system.h"

#include <deal.II/base/point.h>

#include <deal.II/lac/petsc_vector.h>

#include <string>
#include <utility>
#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;
  template <int dim>
  class PlasticStrainField;
  class Material;

  // The materials: materials[i] on the cells of material id i.

  /// Values per active cell written beside the fields (DataOut's cell
  /// data): an elastic-plastic body's plastic strain and stress. A stress
  /// is scaled as the stresses, other values are not.
  struct CellField
  {
    std::string           name;
    dealii::Vector<float> values;
    bool                  is_stress = false;
  };

  /// An elastic-plastic body's cell fields: its equivalent plastic strain
  /// and von Mises stress per cell (PlasticStrainField).
  template <int dim>
  std::vector<CellField>
  plastic_cell_fields(const PlasticStrainField<dim> &plasticity);

  /**
   * Write a displacement field, its stress tensor and the scalar stress
   * measures with deal.II's DataOut on curved patches of the element
   * degree, as DIRECTORY/BASENAME_NNNN.pvtu with one .vtu per rank
   * (write_vtu_record()), coordinates and displacements times
   * @p scales.length, stresses times @p scales.stress; returns the .pvtu's
   * name relative to @p directory. The plane models write the section's
   * stress (von Mises, principal stresses, pressure; see
   * StressScalarsPostprocessor), a 3D body the solid's
   * (SolidStressPostprocessor). With @p ghosted_traction (ContactTraction)
   * also the vector field contact_traction, scaled as the stresses. With
   * @p cell_fields (an elastic-plastic body, whose stress is not C : eps of
   * the displacement) those cell values instead of the stress fields.
   */
  template <int dim>
  std::string
  write_deformed_state(
    const ElasticityOperator<dim>            &op,
    const std::vector<Material>              &materials,
    const dealii::PETScWrappers::MPI::Vector &ghosted_u,
    const std::string                        &directory,
    const std::string                        &basename,
    unsigned int                              index,
    const FieldScales                        &scales           = {},
    const dealii::PETScWrappers::MPI::Vector *ghosted_traction = nullptr,
    const std::vector<CellField>             *cell_fields      = nullptr);

  /**
   * write_deformed_state() for a sphere (Material axisymmetric), and from
   * the same patches a 3D view: the meridian revolved about its axis
   * through @p angle_degrees (RevolvedView), about one sector per 10
   * degrees; the sphere's centre @p centre and radius @p radius find its
   * surface. Writes DIRECTORY/BASENAME_NNNN.pvtu and BASENAME_3d_NNNN.pvtu,
   * scaled as write_deformed_state(); returns both names relative to
   * @p directory.
   */
  std::pair<std::string, std::string>
  write_deformed_and_revolved_state(
    const ElasticityOperator<2>              &op,
    const std::vector<Material>              &materials,
    const dealii::PETScWrappers::MPI::Vector &ghosted_u,
    const dealii::Point<2>                   &centre,
    double                                    radius,
    double                                    angle_degrees,
    const std::string                        &directory,
    const std::string                        &basename,
    unsigned int                              index,
    const FieldScales                        &scales           = {},
    const dealii::PETScWrappers::MPI::Vector *ghosted_traction = nullptr);
} // namespace DiskImpact
