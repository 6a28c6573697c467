#include "tasks/impact_convergence_study.h"

#include "csv_table.h"
#include "parameters.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// Refinement ratio and expected order of each factor.
    struct FactorSequence
    {
      std::string  name;
      unsigned int levels;
      double       ratio;
      double       expected_order;
    };

    std::string
    describe(const StudyRun &run)
    {
      std::ostringstream line;
      line << std::setw(10) << run.factor << std::setw(3) << run.level
           << std::setw(8) << run.summary.n_dofs << std::setw(12)
           << std::scientific << std::setprecision(3) << run.summary.time_step
           << std::fixed << std::setprecision(8) << std::setw(13)
           << run.summary.epsilon << std::scientific << std::setprecision(1)
           << std::setw(10) << run.summary.energy_error << std::fixed
           << std::setprecision(1) << std::setw(8) << run.wall_time << " s\n";
      return line.str();
    }
  } // namespace

  void
  ImpactConvergenceStudy::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact convergence");
    prm.declare_entry("Mesh levels",
                      "3",
                      Patterns::Integer(1, 6),
                      "Runs with every element size and the time step halved "
                      "0, 1, ... times (global refinements + 1, twice the "
                      "elements across the contact, half the grading, half "
                      "the time step) [-]; 1: no mesh study.");
    prm.declare_entry("Time step levels",
                      "1",
                      Patterns::Integer(1, 8),
                      "Runs with the time step alone halved 0, 1, ... times "
                      "[-]: a diagnostic, reported but not added to the error "
                      "bar, which the mesh sequence (with its time step) "
                      "already carries.");
    prm.declare_entry("Penalty levels",
                      "3",
                      Patterns::Integer(1, 6),
                      "Runs with the penalty factor multiplied by 4 0, 1, "
                      "... times [-].");
    prm.leave_subsection();
  }

  void
  ImpactConvergenceStudy::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact convergence");
    mesh_levels      = prm.get_integer("Mesh levels");
    time_step_levels = prm.get_integer("Time step levels");
    penalty_levels   = prm.get_integer("Penalty levels");
    prm.leave_subsection();
  }

  Parameters
  ImpactConvergenceStudy::refined(const Parameters  &parameters,
                                  const std::string &factor,
                                  const unsigned int level)
  {
    Parameters finer = parameters;
    if (factor == "mesh")
      {
        finer.geometry.set_global_refinements(
          parameters.geometry.global_refinements() + level);
        finer.impact = parameters.impact.with_mesh_refined(level);
        finer.time_integrator =
          parameters.time_integrator.with_time_step_scaled(
            std::pow(0.5, level));
      }
    else if (factor == "time step")
      finer.time_integrator =
        parameters.time_integrator.with_time_step_scaled(std::pow(0.5, level));
    else
      finer.contact.set_penalty_factor(parameters.contact.penalty_factor() *
                                       std::pow(4., level));
    return finer;
  }

  ConvergedEpsilon
  ImpactConvergenceStudy::run(const Parameters &parameters,
                              MPI_Comm          communicator,
                              std::ostream     *log) const
  {
    const std::vector<FactorSequence> sequences{
      {"mesh", mesh_levels, 2., 2.},
      {"time step", time_step_levels, 2., 2.},
      {"penalty", penalty_levels, 4., 1.}};
    auto timed_run = [&](const Parameters  &point,
                         const std::string &factor,
                         const unsigned int level) {
      const auto start = std::chrono::steady_clock::now();
      StudyRun run{factor, level, point.impact.run(point, communicator, false)};
      run.wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      if (log != nullptr)
        *log << describe(run) << std::flush;
      return run;
    };

    ConvergedEpsilon result;
    if (log != nullptr)
      *log << "    factor  l    DoFs   dt [R/c]      epsilon   energy"
              " err.  time\n";
    result.runs.push_back(timed_run(parameters, "base", 0));
    result.base    = result.runs.front().summary;
    result.epsilon = result.base.epsilon;
    for (const auto &sequence : sequences)
      {
        if (sequence.levels < 2)
          continue;
        std::vector<double> values{result.base.epsilon};
        for (unsigned int level = 1; level < sequence.levels; ++level)
          {
            result.runs.push_back(timed_run(
              refined(parameters, sequence.name, level), sequence.name, level));
            values.push_back(result.runs.back().summary.epsilon);
          }
        const auto estimate =
          richardson_estimate(values, sequence.ratio, sequence.expected_order);
        result.factors.push_back(sequence.name);
        result.estimates.push_back(estimate);
        // The mesh sequence halves dt as well: the time-step sequence is a
        // diagnostic, its error already part of the mesh's.
        if (sequence.name == "time step")
          continue;
        result.epsilon += estimate.extrapolated - result.base.epsilon;
        result.error += estimate.error;
      }
    return result;
  }

  CsvTable
  ImpactConvergenceStudy::runs_table(const ConvergedEpsilon &result)
  {
    CsvTable table({"factor",
                    "level",
                    "n_dofs",
                    "time_step",
                    "epsilon",
                    "contact_time",
                    "delta_max",
                    "force_max",
                    "energy_error",
                    "steps",
                    "wall_time"});
    for (const auto &run : result.runs)
      {
        table.start_row();
        table.add(run.factor);
        table.add(run.level);
        table.add(run.summary.n_dofs);
        for (const double value : {run.summary.time_step,
                                   run.summary.epsilon,
                                   run.summary.contact_time,
                                   run.summary.delta_max,
                                   run.summary.force_max,
                                   run.summary.energy_error})
          table.add(value);
        table.add(run.summary.steps);
        table.add(run.wall_time);
      }
    return table;
  }

  CsvTable
  ImpactConvergenceStudy::estimates_table(const ConvergedEpsilon &result)
  {
    CsvTable table(
      {"factor", "observed_order", "clean", "limit", "correction", "error"});
    for (unsigned int i = 0; i < result.factors.size(); ++i)
      {
        const auto &e = result.estimates[i];
        table.start_row();
        table.add(result.factors[i]);
        table.add(e.order);
        table.add(e.clean ? 1 : 0);
        table.add(e.extrapolated);
        table.add(e.extrapolated - result.base.epsilon);
        table.add(e.error);
      }
    table.start_row();
    table.add(std::string("total"));
    table.add_empty();
    table.add_empty();
    table.add(result.epsilon);
    table.add(result.epsilon - result.base.epsilon);
    table.add(result.error);
    return table;
  }

  void
  run_impact_convergence(const Parameters &parameters, MPI_Comm communicator)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    ConditionalOStream pcout(std::cout, root);
    pcout << "Convergence study of epsilon at v = "
          << parameters.impact.velocity() << " c\n";
    const auto result =
      parameters.impact_convergence.run(parameters,
                                        communicator,
                                        root ? &std::cout : nullptr);
    const std::string &directory = parameters.run.output_directory;
    if (root)
      {
        ImpactConvergenceStudy::runs_table(result).write(
          directory + "/impact_convergence.csv");
        ImpactConvergenceStudy::estimates_table(result).write(
          directory + "/epsilon_estimate.csv");
      }
    std::ostringstream out;
    out << "  factor      order   limit        error\n";
    for (unsigned int i = 0; i < result.factors.size(); ++i)
      {
        const auto &e = result.estimates[i];
        out << std::setw(10) << result.factors[i] << std::fixed
            << std::setprecision(2) << std::setw(7) << e.order
            << std::setprecision(8) << std::setw(13) << e.extrapolated
            << std::scientific << std::setprecision(2) << std::setw(10)
            << e.error << (e.clean ? "" : "  (order not clean)") << '\n';
      }
    out << std::fixed << std::setprecision(8)
        << "  epsilon = " << result.epsilon << " +- " << std::scientific
        << std::setprecision(2) << result.error << '\n';
    pcout << out.str();
  }
} // namespace DiskImpact
