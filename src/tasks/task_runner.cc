#include "tasks/task_runner.h"

#include "base/parameters.h"
#include "base/run_error.h"
#include "output/output_directory.h"
#include "tasks/impact_convergence_study.h"
#include "tasks/impact_task.h"
#include "tasks/modal_analysis_task.h"
#include "tasks/run_checks.h"
#include "tasks/sweep_task.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <iostream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The names of every result file a task writes (shell wildcards):
    /// what an earlier run may have left in the output directory.
    const std::vector<std::string> result_patterns{
      "used_parameters.prm",
      "used_parameters.json",
      // modal analysis, modal convergence
      "modes.csv",
      "analytic_modes.csv",
      "modes.pvd",
      "modes_*.vtu",
      "modes_*.pvtu",
      "modal_convergence.csv",
      // quasistatic contact
      "contact_law.csv",
      "pressure_profile.csv",
      "contact.pvd",
      "contact_*.vtu",
      "contact_*.pvtu",
      // impact, impact convergence, sweep
      "summary.csv",
      "impact.csv",
      "mode_energies.csv",
      "impact.h5",
      "impact.pvd",
      "impact_*.vtu",
      "impact_*.pvtu",
      "impact_convergence.csv",
      "epsilon_estimate.csv",
      "restitution.csv",
      "restitution.h5",
      // restitution law
      "restitution_law.csv",
      "restitution_law.json",
      // reference models, modal expansion impact
      "reference_*.csv",
      "modal_expansion.csv",
      "modal_expansion_modes.csv",
      "modal_extrapolation.csv"};

    /// Run the task of @p parameters.
    void
    run_dispatched(const Parameters &parameters,
                   const bool        resume,
                   MPI_Comm          communicator)
    {
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
            run_sweep(parameters, resume, communicator);
            break;
          case Task::reference_models:
            parameters.reference_models.run(parameters, communicator);
            break;
          case Task::modal_expansion_impact:
            parameters.modal_expansion.run(parameters, communicator);
            break;
          case Task::restitution_law:
            parameters.restitution_law.run(parameters, resume, communicator);
            break;
        }
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
    // Everything that can be checked is checked before anything is
    // written.
    check_before_output(parameters, communicator);
    const OutputDirectory directory(parameters.run.output_directory,
                                    communicator);
    const bool            resume = parameters.run.runs_sweep() &&
                        sweep_resumes(parameters, prm, communicator);
    // Kept: a resumed sweep's table; the reference models' other tables
    // (the models share one output directory, one file each).
    directory.remove_results(
      result_patterns,
      resume ? sweep_result_files() :
      parameters.run.task == Task::reference_models ?
               parameters.reference_models.other_models_files() :
               std::vector<std::string>());
    directory.write_parameters(prm);

    pcout << "diskimpact: " << Utilities::MPI::n_mpi_processes(communicator)
          << " MPI rank(s), output in " << parameters.run.output_directory
          << "\nGeometry: " << parameters.geometry.description() << '\n';
    parameters.material.print_summary(pcout);
    parameters.units.print_summary(pcout);

    try
      {
        run_dispatched(parameters, resume, communicator);
      }
    catch (const RunError &)
      {
        // A run that failed (on all ranks alike) leaves no results that
        // could pass for its own; a sweep keeps its table, which marks the
        // points not done.
        auto keep = resume || parameters.run.runs_sweep() ?
                      sweep_result_files() :
                      std::vector<std::string>();
        keep.insert(keep.end(),
                    {"used_parameters.prm", "used_parameters.json"});
        directory.remove_results(result_patterns, keep);
        throw;
      }
  }
} // namespace DiskImpact
