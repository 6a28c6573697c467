#include "output/state_output.h"

#include "elasticity/elasticity_operator.h"
#include "elasticity/material.h"
#include "elasticity/stress_postprocessor.h"

#include <deal.II/numerics/data_out.h>

namespace DiskImpact
{
  using namespace dealii;

  std::string
  write_deformed_state(const ElasticityOperator         &op,
                       const Material                   &material,
                       const PETScWrappers::MPI::Vector &ghosted_u,
                       const std::string                &directory,
                       const std::string                &basename,
                       const unsigned int                index)
  {
    DataOut<2> data_out;
    data_out.attach_dof_handler(op.get_dof_handler());
    data_out.add_data_vector(
      ghosted_u,
      std::vector<std::string>(2, "displacement"),
      DataOut<2>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        2, DataComponentInterpretation::component_is_part_of_vector));
    const StressPostprocessor stress(material);
    data_out.add_data_vector(ghosted_u, stress);
    const StressScalarsPostprocessor stress_scalars(material);
    data_out.add_data_vector(ghosted_u, stress_scalars);
    data_out.build_patches(op.get_mapping(),
                           op.degree(),
                           DataOut<2>::curved_inner_cells);
    DataOutBase::VtkFlags flags;
    flags.compression_level =
      DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed;
    data_out.set_flags(flags);
    return data_out.write_vtu_with_pvtu_record(
      directory + "/",
      basename,
      index,
      op.get_dof_handler().get_communicator(),
      4);
  }
} // namespace DiskImpact
