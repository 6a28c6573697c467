#include "elasticity/largest_von_mises.h"

#include "elasticity/stress_postprocessor.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  StressPeak
  largest_von_mises(const Mapping<2>                 &mapping,
                    const DoFHandler<2>              &dof_handler,
                    const std::vector<Material>      &materials,
                    const PETScWrappers::MPI::Vector &u,
                    const Point<2>                   &center,
                    const double                      reach)
  {
    const auto         models = section_stress_models(materials);
    const QIterated<2> quadrature(QGauss<1>(2), 3);
    FEValues<2>        fe_values(mapping,
                          dof_handler.get_fe(),
                          quadrature,
                          update_values | update_gradients |
                            update_quadrature_points);
    const unsigned int n_q        = quadrature.size();
    const unsigned int components = dof_handler.get_fe().n_components();
    DataPostprocessorInputs::Vector<2> inputs;
    inputs.solution_values.resize(n_q, Vector<double>(components));
    inputs.solution_gradients.resize(n_q,
                                     std::vector<Tensor<1, 2>>(components));
    StressPeak peak;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          (reach <= 0. ||
           cell->center().distance(center) <= reach + cell->diameter()))
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(u, inputs.solution_values);
          fe_values.get_function_gradients(u, inputs.solution_gradients);
          inputs.evaluation_points = fe_values.get_quadrature_points();
          inputs.template set_cell<2>(cell);
          const auto &model = section_stress_model_of(models, inputs);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const double von_mises =
                std::sqrt(1.5) *
                deviator(model.evaluate(inputs, q).three_dimensional()).norm();
              if (von_mises > peak.von_mises)
                peak = {von_mises, inputs.evaluation_points[q]};
            }
        }
    // The largest over the ranks, and the point from the rank that has it.
    const MPI_Comm communicator = dof_handler.get_communicator();
    const auto     largest =
      Utilities::MPI::min_max_avg(peak.von_mises, communicator);
    peak.von_mises = largest.max;
    peak.location =
      Utilities::MPI::broadcast(communicator, peak.location, largest.max_index);
    return peak;
  }
} // namespace DiskImpact
