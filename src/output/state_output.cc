#include "output/state_output.h"

#include "elasticity/elasticity_operator.h"
#include "elasticity/plastic_strain_field.h"
#include "elasticity/solid_stress_postprocessor.h"
#include "elasticity/stress_postprocessor.h"
#include "material/material.h"
#include "output/revolved_view.h"
#include "output/vtu_record.h"

#include <deal.II/numerics/data_out.h>

#include <cmath>
#include <memory>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// DataOut with the field names and kinds public, for RevolvedView,
    /// and its patches scalable to the units of the files.
    template <int dim>
    class ScaledOutput : public DataOut<dim>
    {
    public:
      using DataOut<dim>::get_dataset_names;
      using DataOut<dim>::get_nonscalar_data_ranges;

      /// Displacements and coordinates times scales.length, stresses
      /// times scales.stress.
      void
      scale(const FieldScales &scales, const std::vector<CellField> *cells)
      {
        if (scales.length == 1. && scales.stress == 1.)
          return;
        scale_patches(this->patches,
                      get_dataset_names(),
                      scales.length,
                      [&](const std::string &name) {
                        if (name == "displacement")
                          return scales.length;
                        if (cells)
                          for (const CellField &field : *cells)
                            if (field.name == name && !field.is_stress)
                              return 1.;
                        return scales.stress;
                      });
      }
    };

    /// The stress fields of a state: the section's tensor and scalars in
    /// two dimensions, the solid's in three.
    template <int dim>
    std::vector<std::unique_ptr<DataPostprocessor<dim>>>
    stress_fields(const std::vector<Material> &materials)
    {
      std::vector<std::unique_ptr<DataPostprocessor<dim>>> fields;
      if constexpr (dim == 2)
        {
          fields.push_back(std::make_unique<StressPostprocessor>(materials));
          fields.push_back(
            std::make_unique<StressScalarsPostprocessor>(materials));
        }
      else
        fields.push_back(std::make_unique<SolidStressPostprocessor>(materials));
      return fields;
    }

    /// The patches of the displacement and its stresses (the
    /// postprocessors outlive the DataOut that points to them).
    template <int dim>
    struct StatePatches
    {
      StatePatches(const ElasticityOperator<dim>    &op,
                   const std::vector<Material>      &materials,
                   const PETScWrappers::MPI::Vector &ghosted_u,
                   const FieldScales                &scales,
                   const PETScWrappers::MPI::Vector *ghosted_traction,
                   const std::vector<CellField>     *cell_fields)
          : stresses(cell_fields ?
                       std::vector<std::unique_ptr<DataPostprocessor<dim>>>() :
                       stress_fields<dim>(materials))
      {
        data_out.attach_dof_handler(op.get_dof_handler());
        const std::vector<
          DataComponentInterpretation::DataComponentInterpretation>
          vector_field(
            dim, DataComponentInterpretation::component_is_part_of_vector);
        data_out.add_data_vector(ghosted_u,
                                 std::vector<std::string>(dim, "displacement"),
                                 DataOut<dim>::type_dof_data,
                                 vector_field);
        if (ghosted_traction)
          data_out.add_data_vector(*ghosted_traction,
                                   std::vector<std::string>(dim,
                                                            "contact_traction"),
                                   DataOut<dim>::type_dof_data,
                                   vector_field);
        for (const auto &field : stresses)
          data_out.add_data_vector(ghosted_u, *field);
        if (cell_fields)
          for (const CellField &field : *cell_fields)
            data_out.add_data_vector(field.values,
                                     field.name,
                                     DataOut<dim>::type_cell_data);
        data_out.build_patches(op.get_mapping(),
                               op.degree(),
                               DataOut<dim>::curved_inner_cells);
        data_out.scale(scales, cell_fields);
      }

      const std::vector<std::unique_ptr<DataPostprocessor<dim>>> stresses;
      ScaledOutput<dim>                                          data_out;
    };

    DataOutBase::VtkFlags
    vtu_flags()
    {
      DataOutBase::VtkFlags flags;
      flags.compression_level =
        DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed;
      return flags;
    }
  } // namespace

  template <int dim>
  std::vector<CellField>
  plastic_cell_fields(const PlasticStrainField<dim> &plasticity)
  {
    return {{"equivalent_plastic_strain",
             plasticity.equivalent_plastic_strain_per_cell(),
             false},
            {"von_mises_stress", plasticity.von_mises_stress_per_cell(), true}};
  }

  template std::vector<CellField>
  plastic_cell_fields(const PlasticStrainField<2> &);
  template std::vector<CellField>
  plastic_cell_fields(const PlasticStrainField<3> &);

  template <int dim>
  std::string
  write_deformed_state(const ElasticityOperator<dim>    &op,
                       const std::vector<Material>      &material,
                       const PETScWrappers::MPI::Vector &ghosted_u,
                       const std::string                &directory,
                       const std::string                &basename,
                       const unsigned int                index,
                       const FieldScales                &scales,
                       const PETScWrappers::MPI::Vector *ghosted_traction,
                       const std::vector<CellField>     *cell_fields)
  {
    StatePatches<dim> state(
      op, material, ghosted_u, scales, ghosted_traction, cell_fields);
    state.data_out.set_flags(vtu_flags());
    return write_vtu_record(state.data_out,
                            directory,
                            basename,
                            index,
                            op.get_dof_handler().get_communicator());
  }

  template std::string
  write_deformed_state(const ElasticityOperator<2> &,
                       const std::vector<Material> &,
                       const PETScWrappers::MPI::Vector &,
                       const std::string &,
                       const std::string &,
                       unsigned int,
                       const FieldScales &,
                       const PETScWrappers::MPI::Vector *,
                       const std::vector<CellField> *);
  template std::string
  write_deformed_state(const ElasticityOperator<3> &,
                       const std::vector<Material> &,
                       const PETScWrappers::MPI::Vector &,
                       const std::string &,
                       const std::string &,
                       unsigned int,
                       const FieldScales &,
                       const PETScWrappers::MPI::Vector *,
                       const std::vector<CellField> *);

  std::pair<std::string, std::string>
  write_deformed_and_revolved_state(
    const ElasticityOperator<2>      &op,
    const std::vector<Material>      &material,
    const PETScWrappers::MPI::Vector &ghosted_u,
    const Point<2>                   &centre,
    const double                      radius,
    const double                      angle_degrees,
    const std::string                &directory,
    const std::string                &basename,
    const unsigned int                index,
    const FieldScales                &scales,
    const PETScWrappers::MPI::Vector *ghosted_traction)
  {
    // One set of patches (the stresses evaluated once) for both files.
    StatePatches<2> state(
      op, material, ghosted_u, scales, ghosted_traction, nullptr);
    state.data_out.set_flags(vtu_flags());
    const MPI_Comm    communicator = op.get_dof_handler().get_communicator();
    const std::string flat         = write_vtu_record(
      state.data_out, directory, basename, index, communicator);
    // About one sector per 10 degrees.
    const auto sectors =
      static_cast<unsigned int>(std::max(1., std::ceil(angle_degrees / 10.)));
    RevolvedView view(state.data_out.get_patches(),
                      state.data_out.get_dataset_names(),
                      state.data_out.get_nonscalar_data_ranges(),
                      "hoop_stress",
                      centre * scales.length,
                      radius * scales.length,
                      angle_degrees * M_PI / 180.,
                      sectors);
    view.set_flags(vtu_flags());
    return {
      flat,
      write_vtu_record(view, directory, basename + "_3d", index, communicator)};
  }
} // namespace DiskImpact
