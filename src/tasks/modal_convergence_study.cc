#include "tasks/modal_convergence_study.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "base/run_error.h"
#include "modal/modal_analysis.h"
#include "output/csv_table.h"
#include "run/parameters.h"
#include "run/task_registry.h"
#include "tasks/run_checks.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  void
  ModalConvergenceStudy::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal convergence");
    prm.declare_entry("Degrees",
                      "1, 2, 3",
                      Patterns::List(Patterns::Integer(1, 4), 1),
                      "Element degrees k of the study.");
    prm.declare_entry("Refinement levels",
                      "1, 2, 3, 4",
                      Patterns::List(Patterns::Integer(0, 10), 2),
                      "Global refinements of the study's meshes, ascending "
                      "(replaces 'Global refinements' of subsection "
                      "Geometry).");
    prm.declare_entry("Modes compared",
                      "10",
                      Patterns::Integer(1, 200),
                      "Number of distinct analytic modes (n, l, family), "
                      "lowest first, whose errors are tabulated.");
    prm.leave_subsection();
  }

  void
  ModalConvergenceStudy::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal convergence");
    degrees           = get_count_list(prm, "Degrees");
    refinement_levels = get_count_list(prm, "Refinement levels");
    n_modes_compared  = prm.get_integer("Modes compared");
    prm.leave_subsection();
    require(std::is_sorted(refinement_levels.begin(),
                           refinement_levels.end()) &&
              std::adjacent_find(refinement_levels.begin(),
                                 refinement_levels.end()) ==
                refinement_levels.end(),
            "Modal convergence: 'Refinement levels' must be strictly "
            "ascending");
  }

  Parameters
  ModalConvergenceStudy::finest(const Parameters &parameters) const
  {
    Parameters finest = parameters;
    finest.finite_element.degree =
      *std::max_element(degrees.begin(), degrees.end());
    finest.geometry.set_global_refinements(refinement_levels.back());
    return finest;
  }

  Parameters
  ModalConvergenceStudy::coarsest(const Parameters &parameters) const
  {
    Parameters coarsest = parameters;
    coarsest.finite_element.degree =
      *std::min_element(degrees.begin(), degrees.end());
    coarsest.geometry.set_global_refinements(refinement_levels.front());
    // A full disk has every mode of order n >= 1 twice.
    coarsest.modal_solver.set_n_elastic_modes(
      n_modes_compared * (parameters.geometry.has_symmetry_boundary() ? 1 : 2));
    return coarsest;
  }

  void
  ModalConvergenceStudy::run(const Parameters &parameters,
                             MPI_Comm          communicator) const
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(communicator) ==
                               0);
    // Times the modal analyses; a timer without communicator prints nothing
    // when an error unwinds.
    TimerOutput timer(pcout, TimerOutput::never, TimerOutput::wall_times);

    // The distinct analytic modes to follow, and how many computed modes
    // (with multiplicity) it takes to reach the last of them.
    const bool half = parameters.geometry.has_symmetry_boundary();
    const auto reference =
      analytic_free_modes(parameters.geometry, parameters.material);
    std::vector<Reference::ModeLabel> targets;
    unsigned int                      n_elastic_needed = 0;
    for (unsigned int count = n_modes_compared;
         targets.size() < n_modes_compared;
         count *= 2)
      {
        targets.clear();
        const auto lowest = reference->lowest_modes(count, half);
        for (unsigned int i = 0; i < lowest.size(); ++i)
          if (targets.size() < n_modes_compared &&
              std::find(targets.begin(), targets.end(), lowest[i]) ==
                targets.end())
            {
              targets.push_back(lowest[i]);
              n_elastic_needed = i + 1;
            }
      }

    CsvTable           table({"degree",
                              "refinements",
                              "n_dofs",
                              "h",
                              "mode",
                              "n",
                              "l",
                              "family",
                              "omega",
                              "omega_exact",
                              "relative_error",
                              "observed_order"});
    std::ostringstream summary;
    for (const unsigned int degree : degrees)
      {
        std::vector<std::optional<double>> previous_error(targets.size());
        double                             previous_h = 0.;
        for (const unsigned int level : refinement_levels)
          {
            BodyGeometry geometry = parameters.geometry;
            geometry.set_global_refinements(level);
            ModalAnalysis analysis(geometry,
                                   parameters.material,
                                   degree,
                                   parameters.modal_solver,
                                   communicator,
                                   timer);
            const auto    modes = analysis.run(n_elastic_needed);
            const double  h     = analysis.mesh_size();
            pcout << "Q" << degree << ", " << level << " refinements, "
                  << analysis.n_dofs() << " DoFs, h = " << h << std::endl;

            for (unsigned int t = 0; t < targets.size(); ++t)
              {
                const auto match =
                  std::find_if(modes.begin(), modes.end(), [&](const auto &m) {
                    return m.label == targets[t];
                  });
                table.start_row();
                table.add(degree);
                table.add(level);
                table.add(static_cast<long long>(analysis.n_dofs()));
                table.add(h);
                table.add(t);
                table.add(targets[t].n);
                table.add(targets[t].l);
                table.add(to_string(targets[t].family));
                std::optional<double> error;
                if (match != modes.end())
                  {
                    error = match->relative_error();
                    table.add(match->omega);
                    table.add(match->omega_exact);
                    table.add(*error);
                  }
                else
                  {
                    // No computed mode carries this label on this mesh.
                    table.add_empty();
                    table.add(reference->omega(targets[t]));
                    table.add_empty();
                  }
                if (error && previous_error[t] && *error != 0.)
                  {
                    const double order =
                      std::log(std::abs(*previous_error[t] / *error)) /
                      std::log(previous_h / h);
                    table.add(order);
                    summary << "  Q" << degree << " level " << std::setw(2)
                            << level << "  mode " << std::setw(2) << t << " ("
                            << targets[t].n << "," << targets[t].l << ","
                            << to_string(targets[t].family) << ")  error "
                            << std::scientific << std::setprecision(3) << *error
                            << "  order " << std::fixed << std::setprecision(2)
                            << order << '\n';
                  }
                else
                  table.add_empty();
                previous_error[t] = error;
              }
            previous_h = h;
          }
      }
    pcout << "Observed orders (expected 2k):\n" << summary.str();
    on_root(communicator, [&]() {
      table.write(parameters.run.output_directory + "/modal_convergence.csv");
    });
    timer.print_summary();
  }

  namespace
  {
    TaskEntry
    modal_convergence_task()
    {
      TaskEntry task;
      task.name         = "modal convergence";
      task.description  = "the modal analysis on a sequence of meshes and "
                          "degrees, with observed orders "
                          "(modal_convergence.csv).";
      task.traits.modal = true;
      task.result_files = {"modal_convergence.csv"};
      add_own_parameters<ModalConvergenceStudy>(task);
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        parameters.task_parameters<ModalConvergenceStudy>().run(parameters,
                                                                communicator);
      };
      task.build_largest_mesh = [](const Parameters &parameters,
                                   Triangulation<2> &mesh,
                                   const auto       &cell_budget) {
        in_context("Modal convergence: the finest of 'Refinement levels' and "
                   "'Degrees'",
                   [&]() {
                     const Parameters finest =
                       parameters.task_parameters<ModalConvergenceStudy>()
                         .finest(parameters);
                     finest.geometry.create_triangulation(
                       mesh, cell_budget(finest.finite_element.degree));
                   });
        check_mode_count(parameters.task_parameters<ModalConvergenceStudy>()
                           .coarsest(parameters),
                         "Modal convergence: 'Modes compared' on the "
                         "coarsest of 'Refinement levels' and 'Degrees'");
      };
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(modal_convergence_task())
} // namespace DiskImpact
