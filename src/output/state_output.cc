#include "output/state_output.h"

#include "elasticity/elasticity_operator.h"
#include "elasticity/material.h"
#include "elasticity/stress_postprocessor.h"
#include "output/revolved_view.h"

#include <deal.II/numerics/data_out.h>

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// DataOut with the field names and kinds public, for RevolvedView.
    class MeridianOutput : public DataOut<2>
    {
    public:
      using DataOut<2>::get_dataset_names;
      using DataOut<2>::get_nonscalar_data_ranges;
    };

    /// The patches of the displacement and its stresses (the
    /// postprocessors outlive the DataOut that points to them).
    struct StatePatches
    {
      StatePatches(const ElasticityOperator         &op,
                   const std::vector<Material>      &material,
                   const PETScWrappers::MPI::Vector &ghosted_u)
          : stress(material)
          , stress_scalars(material)
      {
        data_out.attach_dof_handler(op.get_dof_handler());
        data_out.add_data_vector(
          ghosted_u,
          std::vector<std::string>(2, "displacement"),
          DataOut<2>::type_dof_data,
          std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            2, DataComponentInterpretation::component_is_part_of_vector));
        data_out.add_data_vector(ghosted_u, stress);
        data_out.add_data_vector(ghosted_u, stress_scalars);
        data_out.build_patches(op.get_mapping(),
                               op.degree(),
                               DataOut<2>::curved_inner_cells);
      }

      const StressPostprocessor        stress;
      const StressScalarsPostprocessor stress_scalars;
      MeridianOutput                   data_out;
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

  std::string
  write_deformed_state(const ElasticityOperator         &op,
                       const std::vector<Material>      &material,
                       const PETScWrappers::MPI::Vector &ghosted_u,
                       const std::string                &directory,
                       const std::string                &basename,
                       const unsigned int                index)
  {
    StatePatches state(op, material, ghosted_u);
    state.data_out.set_flags(vtu_flags());
    return state.data_out.write_vtu_with_pvtu_record(
      directory + "/",
      basename,
      index,
      op.get_dof_handler().get_communicator(),
      4);
  }

  std::pair<std::string, std::string>
  write_deformed_and_revolved_state(const ElasticityOperator         &op,
                                    const std::vector<Material>      &material,
                                    const PETScWrappers::MPI::Vector &ghosted_u,
                                    const Point<2>                   &centre,
                                    const double                      radius,
                                    const double       angle_degrees,
                                    const std::string &directory,
                                    const std::string &basename,
                                    const unsigned int index)
  {
    // One set of patches (the stresses evaluated once) for both files.
    StatePatches state(op, material, ghosted_u);
    state.data_out.set_flags(vtu_flags());
    const MPI_Comm    communicator = op.get_dof_handler().get_communicator();
    const std::string flat         = state.data_out.write_vtu_with_pvtu_record(
      directory + "/", basename, index, communicator, 4);
    // About one sector per 10 degrees.
    const auto sectors =
      static_cast<unsigned int>(std::max(1., std::ceil(angle_degrees / 10.)));
    RevolvedView view(state.data_out.get_patches(),
                      state.data_out.get_dataset_names(),
                      state.data_out.get_nonscalar_data_ranges(),
                      "hoop_stress",
                      centre,
                      radius,
                      angle_degrees * M_PI / 180.,
                      sectors);
    view.set_flags(vtu_flags());
    return {flat,
            view.write_vtu_with_pvtu_record(
              directory + "/", basename + "_3d", index, communicator, 4)};
  }
} // namespace DiskImpact
