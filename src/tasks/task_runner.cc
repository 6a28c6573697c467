#include "tasks/task_runner.h"

#include "base/run_error.h"
#include "output/output_directory.h"
#include "run/parameters.h"
#include "run/task_registry.h"
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
    /// what an earlier run of any task may have left in the output
    /// directory.
    std::vector<std::string>
    result_patterns()
    {
      std::vector<std::string> patterns{"used_parameters.prm",
                                        "used_parameters.json"};
      for (const auto &task : Tasks::all())
        patterns.insert(patterns.end(),
                        task.result_files.begin(),
                        task.result_files.end());
      return patterns;
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
    const TaskEntry      &task = parameters.task();
    const bool            resume =
      task.traits.sweeps && sweep_resumes(parameters, prm, communicator);
    // Kept: a resumed sweep's table; what the task keeps (the reference
    // models' other tables: the models share one output directory, one
    // file each).
    directory.remove_results(result_patterns(),
                             resume            ? sweep_result_files() :
                             task.kept_results ? task.kept_results(parameters) :
                                                 std::vector<std::string>());
    directory.write_parameters(prm);

    pcout << "diskimpact: " << Utilities::MPI::n_mpi_processes(communicator)
          << " MPI rank(s), output in " << parameters.run.output_directory
          << "\nGeometry: " << parameters.geometry.description() << '\n';
    parameters.material.print_summary(pcout,
                                      parameters.geometry.dimension() == 3);
    parameters.units.print_summary(pcout);

    try
      {
        task.run(parameters, resume, communicator);
      }
    catch (const RunError &)
      {
        // A run that failed (on all ranks alike) leaves no results that
        // could pass for its own; a sweep keeps its table, which marks the
        // points not done.
        auto keep = resume || task.traits.sweeps ? sweep_result_files() :
                                                   std::vector<std::string>();
        keep.insert(keep.end(),
                    {"used_parameters.prm", "used_parameters.json"});
        directory.remove_results(result_patterns(), keep);
        throw;
      }
  }
} // namespace DiskImpact
