#include "tasks/task_runner.h"

#include "base/parameters.h"
#include "tasks/impact_convergence_study.h"
#include "tasks/impact_task.h"
#include "tasks/modal_analysis_task.h"
#include "tasks/sweep_task.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    void
    prepare_output_directory(const Parameters       &parameters,
                             const ParameterHandler &prm,
                             MPI_Comm                communicator)
    {
      const std::string &directory = parameters.run.output_directory;
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          std::filesystem::create_directories(directory);
          const auto style = ParameterHandler::OutputStyle(
            ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder);
          std::ofstream prm_copy(directory + "/used_parameters.prm");
          prm.print_parameters(prm_copy, style);
          std::ofstream json_copy(directory + "/used_parameters.json");
          prm.print_parameters(json_copy, ParameterHandler::JSON);
        }
      MPI_Barrier(communicator);
    }

  } // namespace

  void
  run_task(const Parameters       &parameters,
           const ParameterHandler &prm,
           MPI_Comm                communicator)
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(communicator) ==
                               0);
    prepare_output_directory(parameters, prm, communicator);
    pcout << "diskimpact: " << Utilities::MPI::n_mpi_processes(communicator)
          << " MPI rank(s), output in " << parameters.run.output_directory
          << "\nGeometry: " << parameters.geometry.description() << '\n';
    parameters.material.print_summary(pcout);

    switch (parameters.run.task)
      {
        case Task::modal_analysis:
          run_modal_analysis(parameters, communicator);
          break;
        case Task::modal_convergence:
          parameters.modal_convergence.run(parameters, communicator);
          break;
        case Task::quasistatic_contact:
          parameters.quasistatic_contact.run(parameters, communicator);
          break;
        case Task::impact:
          run_impact(parameters, communicator);
          break;
        case Task::impact_convergence:
          run_impact_convergence(parameters, communicator);
          break;
        case Task::sweep:
          run_sweep(parameters, communicator);
          break;
        case Task::reference_models:
          parameters.reference_models.run(parameters, communicator);
          break;
        case Task::modal_expansion_impact:
          parameters.modal_expansion.run(parameters, communicator);
          break;
      }
  }
} // namespace DiskImpact
