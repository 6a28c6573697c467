#include "base/peak_memory.h"
#include "base/run_error.h"
#include "impact/impact_convergence_study.h"
#include "impact/impact_estimates.h"
#include "impact/impact_mesh.h"
#include "output/csv_table.h"
#include "run/parameters.h"
#include "run/task_registry.h"
#include "tasks/run_checks.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <iomanip>
#include <iostream>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// Why @p e was not extrapolated (empty if it was).
    std::string
    why_not_clean(const RichardsonEstimate &e)
    {
      return e.clean ? "" : "  (not extrapolated: " + e.not_clean_because + ")";
    }

    /// Task 'impact convergence': the study at 'Velocity', printed and
    /// written to impact_convergence.csv and epsilon_estimate.csv.
    void
    run_impact_convergence(const Parameters &parameters, MPI_Comm communicator)
    {
      const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
      ConditionalOStream pcout(std::cout, root);
      pcout << "Convergence study of epsilon at v = "
            << parameters.impact.velocity()
            << " c, runs of rank 0 as they end:\n";
      const auto result =
        ImpactConvergenceStudy(parameters.impact_convergence)
          .run(parameters, communicator, root ? &std::cout : nullptr);
      const std::string &directory = parameters.run.output_directory;
      on_root(communicator, [&]() {
        ImpactConvergenceStudy::runs_table(result).write(
          directory + "/impact_convergence.csv");
        ImpactConvergenceStudy::estimates_table(result).write(
          directory + "/epsilon_estimate.csv");
      });
      std::ostringstream out;
      out << "All runs:\n";
      for (const auto &run : result.runs)
        out << ImpactConvergenceStudy::describe(run);
      out << "  factor      order   limit        error\n";
      for (unsigned int i = 0; i < result.factors.size(); ++i)
        {
          const auto &e = result.estimates[i];
          out << std::setw(10) << result.factors[i] << std::fixed
              << std::setprecision(2) << std::setw(7) << e.order
              << std::setprecision(8) << std::setw(13) << e.extrapolated
              << std::scientific << std::setprecision(2) << std::setw(10)
              << e.error
              << (result.factors[i] == "split" ?
                    "  (the last mesh difference's time-step and mesh parts "
                    "apart)" :
                    why_not_clean(e))
              << '\n';
        }
      out << std::fixed << std::setprecision(8)
          << "  epsilon = " << result.epsilon << " +- " << std::scientific
          << std::setprecision(2) << result.error << '\n';
      const double memory = peak_memory_mb(communicator);
      out << std::fixed << std::setprecision(0) << "  peak memory " << memory
          << " MB (all ranks)\n";
      const double target = parameters.impact_convergence.target_error;
      if (target > 0. && result.error > target)
        out << "  (the target error " << target << " is not reached with "
            << parameters.impact_convergence.largest_mesh_levels
            << " mesh levels)\n";
      pcout << out.str();
    }

    TaskEntry
    impact_convergence_task()
    {
      TaskEntry task;
      task.name           = "impact convergence";
      task.description    = "the impact on ever finer meshes, time steps and "
                            "penalties, epsilon extrapolated with its error bar "
                            "(impact_convergence.csv, epsilon_estimate.csv).";
      task.traits.impacts = true;
      task.traits.partner_body      = true;
      task.traits.one_mesh_per_rank = true;
      task.traits.three_dimensional = true;
      task.traits.plasticity        = true;
      task.result_files = {"impact_convergence.csv", "epsilon_estimate.csv"};
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        run_impact_convergence(parameters, communicator);
      };
      task.check = [](const Parameters &parameters) {
        check_impact_time_step(parameters);
      };
      const auto build =
        [](const Parameters &parameters, auto &mesh, const auto &cell_budget) {
          in_context("Impact convergence: the finest of 'Mesh levels'", [&]() {
            // a degree level's budget is its own degree's
            const Parameters finest =
              ImpactConvergenceStudy(parameters.impact_convergence)
                .finest(parameters);
            create_impact_mesh(finest,
                               mesh,
                               cell_budget(finest.finite_element.degree));
          });
        };
      task.build_largest_mesh       = build;
      task.build_largest_solid_mesh = build;
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(impact_convergence_task())
} // namespace DiskImpact
