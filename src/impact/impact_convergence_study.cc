#include "impact/impact_convergence_study.h"

#include "base/input_error.h"
#include "base/run_error.h"
#include "impact/impact_operators.h"
#include "impact/impact_simulation.h"
#include "impact/measured_contact_grading.h"
#include "output/csv_table.h"
#include "run/parameters.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numeric>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// Refinement ratio and expected order of a factor.
    struct FactorSequence
    {
      std::string name;
      double      ratio;
      double      expected_order;
    };

    /// The study's sequences: mesh (everything together), then the two
    /// diagnostics.
    const std::array<FactorSequence, 3> factor_sequences{
      {{"mesh", 2., 1.}, {"time step", 2., 2.}, {"penalty", 4., 1.}}};

    /// The mesh level and the time level (the number of times the base time
    /// step is halved) of @p run; the penalty runs have neither.
    std::pair<int, int>
    mesh_and_time_level(const StudyRun &run)
    {
      const int l = run.level, k = run.time_halvings;
      if (run.factor == "mesh")
        return {l, l + k};
      if (run.factor == "split")
        return {l - 1, l + k};
      if (run.factor == "time step")
        return {0, l};
      if (run.factor == "base")
        return {0, 0};
      return {-1, -1};
    }

  } // namespace

  Parameters
  ImpactConvergenceStudy::refined(const Parameters  &parameters,
                                  const std::string &factor,
                                  const unsigned int level,
                                  const unsigned int time_halvings) const
  {
    if (time_halvings > 0)
      {
        Parameters finer      = refined(parameters, factor, level);
        finer.time_integrator = finer.time_integrator.with_time_step_scaled(
          std::pow(0.5, time_halvings));
        return finer;
      }
    Parameters finer = parameters;
    if (factor == "mesh")
      {
        // From 'Degree levels from' on a level raises the degree on the mesh
        // of the level before; the penalty factor doubles as k = kappa E2 / h
        // does when h halves.
        const unsigned int mesh_level =
          degree_levels_from > 0 ? std::min(level, degree_levels_from - 1) :
                                   level;
        const unsigned int degree_level = level - mesh_level;
        finer.geometry.set_global_refinements(
          parameters.geometry.global_refinements() + mesh_level);
        finer.impact = parameters.impact.with_mesh_refined(mesh_level);
        finer.finite_element.degree += degree_level;
        finer.contact.stiffen_law(std::pow(2., degree_level));
        finer.time_integrator =
          parameters.time_integrator.with_time_step_scaled(
            std::pow(0.5, level));
      }
    else if (factor == "split")
      {
        // mesh level - 1 with the time step of mesh level @p level
        finer = refined(parameters, "mesh", level - 1);
        finer.time_integrator =
          finer.time_integrator.with_time_step_scaled(0.5);
      }
    else if (factor == "time step")
      finer.time_integrator =
        parameters.time_integrator.with_time_step_scaled(std::pow(0.5, level));
    else
      finer.contact.stiffen_law(std::pow(4., level));
    return finer;
  }

  Parameters
  ImpactConvergenceStudy::finest(const Parameters &parameters) const
  {
    return refined(parameters, "mesh", finest_mesh_levels() - 1);
  }

  std::vector<StudyRun>
  ImpactConvergenceStudy::run_all(const std::vector<StudyRun>   &runs,
                                  const std::vector<Parameters> &points,
                                  MPI_Comm                       communicator,
                                  std::ostream                  *log,
                                  SharedOperators               &shared)
  {
    // Shared out among the ranks, the costliest first, each to the rank
    // with the least work so far; every run on its rank alone.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    std::vector<unsigned int> order(runs.size());
    std::iota(order.begin(), order.end(), 0u);
    auto cost = [&](const unsigned int i) {
      // DoFs x steps: 4 per mesh level, 2 per time level (a penalty run
      // costs the base's; a degree level counts as a mesh level, though it
      // costs about twice the level before it, not four times).
      const auto [m, t] = mesh_and_time_level(runs[i]);
      return m < 0 ? 1. : std::pow(4., m) * std::pow(2., t);
    };
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return cost(a) > cost(b);
                     });
    std::vector<double>       load(n_ranks, 0.);
    std::vector<unsigned int> owner(runs.size());
    for (const unsigned int i : order)
      {
        owner[i] = std::min_element(load.begin(), load.end()) - load.begin();
        load[owner[i]] += cost(i);
      }

    // Each run's results as numbers, summed over the ranks (zero where a
    // rank did not run it).
    constexpr unsigned int n_fields = 14;
    std::vector<double>    fields(n_fields * runs.size(), 0.);
    auto                   run_one = [&](const unsigned int i) {
      const auto    start = std::chrono::steady_clock::now();
      ImpactSummary s;
      try
        {
          // A penalty level has its own mesh level -1: its own operators.
          const int m = mesh_and_time_level(runs[i]).first;
          std::shared_ptr<ImpactOperatorsBase> operators;
          if (m >= 0)
            {
              auto &kept = shared[m];
              if (!kept)
                kept = make_impact_operators(points[i], MPI_COMM_SELF);
              operators = kept;
            }
          s = run_impact(points[i], MPI_COMM_SELF, false, operators);
        }
      catch (const std::exception &e)
        {
          throw std::runtime_error("convergence study, " + runs[i].factor +
                                   " level " + std::to_string(runs[i].level) +
                                   (runs[i].time_halvings > 0 ?
                                                        " (time step halved " +
                                        std::to_string(runs[i].time_halvings) +
                                        " more times)" :
                                                        "") +
                                   ": " + e.what());
        }

      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      const std::array<double, n_fields> values{{s.epsilon,
                                                 s.contact_time,
                                                 s.delta_max,
                                                 s.force_max,
                                                 s.energy_error,
                                                 s.time_step,
                                                 static_cast<double>(s.n_dofs),
                                                 static_cast<double>(s.steps),
                                                 seconds,
                                                 s.schwager_alpha,
                                                 s.one_dof_epsilon,
                                                 s.ramirez_u,
                                                 s.plastic_work,
                                                 s.plastic_strain_max}};
      std::copy(values.begin(), values.end(), &fields[n_fields * i]);
      if (log != nullptr)
        *log << describe({runs[i].factor,
                          runs[i].level,
                          runs[i].time_halvings,
                          s,
                          seconds})
             << std::flush;
    };
    // A run that fails on one rank fails the study on all (after each rank
    // has ended its own runs).
    collectively(communicator, [&]() {
      for (unsigned int i = 0; i < runs.size(); ++i)
        if (owner[i] == rank)
          run_one(i);
    });
    Utilities::MPI::sum(fields, communicator, fields);

    std::vector<StudyRun> done = runs;
    for (unsigned int i = 0; i < runs.size(); ++i)
      {
        const double *f   = &fields[n_fields * i];
        auto         &s   = done[i].summary;
        s.velocity        = points[i].impact.velocity();
        s.epsilon         = f[0];
        s.contact_time    = f[1];
        s.delta_max       = f[2];
        s.force_max       = f[3];
        s.energy_error    = f[4];
        s.time_step       = f[5];
        s.n_dofs          = static_cast<unsigned int>(f[6]);
        s.steps           = static_cast<unsigned int>(f[7]);
        done[i].wall_time = f[8];
        s.schwager_alpha  = f[9];
        s.one_dof_epsilon = f[10];
        s.ramirez_u       = f[11];
        s.plastic_work       = f[12];
        s.plastic_strain_max = f[13];
      }
    return done;
  }

  namespace
  {
    /// The run of @p result on mesh level @p m with time level @p t (null if
    /// there is none).
    const StudyRun *
    find_run(const ConvergedEpsilon &result, const int m, const int t)
    {
      for (const auto &run : result.runs)
        if (mesh_and_time_level(run) == std::make_pair(m, t))
          return &run;
      return nullptr;
    }

    /// The mesh run with the finest mesh, and on it the finest time step.
    const StudyRun &
    finest_mesh_run(const ConvergedEpsilon &result)
    {
      const StudyRun *finest = &result.runs.front();
      for (const auto &run : result.runs)
        if ((run.factor == "mesh" || run.factor == "base") &&
            mesh_and_time_level(run) > mesh_and_time_level(*finest))
          finest = &run;
      return *finest;
    }
  } // namespace

  void
  ImpactConvergenceStudy::estimate(ConvergedEpsilon &result)
  {
    result.base      = result.runs.front().summary;
    result.epsilon   = result.base.epsilon;
    result.error     = 0.;
    result.time_part = std::numeric_limits<double>::quiet_NaN();
    result.mesh_part = std::numeric_limits<double>::quiet_NaN();
    result.factors.clear();
    result.estimates.clear();
    for (const auto &sequence : factor_sequences)
      {
        // The mesh sequence: its levels with their own time steps.
        std::vector<double> values{result.base.epsilon};
        for (const auto &run : result.runs)
          if (run.factor == sequence.name && run.time_halvings == 0)
            values.push_back(run.summary.epsilon);
        if (values.size() < 2)
          {
            // The second mesh level ran at the halved step at once ('Halve
            // first above'): the split bar is the whole estimate.
            if (sequence.name == "mesh")
              add_separate_time_step_error(result);
            continue;
          }
        const auto limit =
          richardson_estimate(values, sequence.ratio, sequence.expected_order);
        result.factors.push_back(sequence.name);
        result.estimates.push_back(limit);
        // The mesh sequence halves dt and stiffens the penalty as well: the
        // other sequences are diagnostics, their errors part of the mesh's.
        if (sequence.name != "mesh")
          continue;
        result.epsilon += limit.extrapolated - result.base.epsilon;
        result.error += limit.error;
        if (!limit.clean)
          add_separate_time_step_error(result);
      }
  }

  void
  ImpactConvergenceStudy::add_separate_time_step_error(ConvergedEpsilon &result)
  {
    // The finest run (mesh level L, time level T), the run of mesh level
    // L - 1 with the same time step and that mesh's run with twice the
    // step: d = d_t + d_h, the time step's part and the mesh's.
    const StudyRun &finest   = finest_mesh_run(result);
    const auto [L, T]        = mesh_and_time_level(finest);
    const auto *coarser_mesh = find_run(result, L - 1, T);
    const auto *coarser_both = find_run(result, L - 1, T - 1);
    if (L < 1 || coarser_mesh == nullptr || coarser_both == nullptr)
      return;
    result.time_part =
      coarser_mesh->summary.epsilon - coarser_both->summary.epsilon;
    result.mesh_part = finest.summary.epsilon - coarser_mesh->summary.epsilon;
    RichardsonEstimate apart;
    apart.extrapolated  = finest.summary.epsilon;
    apart.order         = std::numeric_limits<double>::quiet_NaN();
    apart.order_scatter = std::numeric_limits<double>::quiet_NaN();
    // The first-order fallback of each part, as for the mesh sequence.
    apart.error =
      3. * (std::abs(result.time_part) + std::abs(result.mesh_part));
    if (T > L)
      {
        // With the time step halved beyond the mesh sequence's, epsilon is
        // the finest run and this is its bar.
        result.epsilon = apart.extrapolated;
        result.error   = apart.error;
      }
    else
      result.error = std::max(result.error, apart.error);
    result.factors.push_back("split");
    result.estimates.push_back(apart);
  }

  std::vector<StudyRun>
  ImpactConvergenceStudy::next_refinement(const ConvergedEpsilon &result) const
  {
    const StudyRun    &finest = finest_mesh_run(result);
    const unsigned int L      = finest.level;
    const unsigned int k      = finest.time_halvings;
    const bool         split  = !std::isnan(result.time_part);
    const bool         time_dominates =
      split && std::abs(result.time_part) >= 0.5 * std::abs(result.mesh_part);
    // A halving costs the last level's run twice over, a mesh level eight
    // times over (twice the steps, four times the DoFs).
    if (k < largest_time_halvings && time_dominates)
      return {{"mesh", L, k + 1, {}, 0.}, {"split", L, k + 1, {}, 0.}};
    if (L + 1 >= largest_mesh_levels)
      return {};
    // The mesh's part dominates, the step is already halved and the finest
    // mesh's own halving moved epsilon by less than the same share of it:
    // the next mesh level keeps the finest step, (L + 1, T), whose time part
    // is that halving's. Its split run, mesh level L at T, is the finest run.
    const auto [m, t]                    = mesh_and_time_level(finest);
    const auto *finest_at_twice_the_step = find_run(result, m, t - 1);
    // Where level 1 ran at the halved step at once ('Halve first above'),
    // its run at the unhalved step comes first: the choice below needs it.
    if (halve_first_above > 0. && L == 1 && k == 1 && split &&
        !time_dominates && finest_at_twice_the_step == nullptr)
      return {{"mesh", 1, 0, {}, 0.}};
    if (k > 0 && split && !time_dominates &&
        finest_at_twice_the_step != nullptr &&
        std::abs(finest.summary.epsilon -
                 finest_at_twice_the_step->summary.epsilon) <
          0.5 * std::abs(result.mesh_part))
      return {{"mesh", L + 1, k - 1, {}, 0.}};
    std::vector<StudyRun> more{{"mesh", L + 1, k, {}, 0.}};
    if (separate_time_step)
      more.push_back({"split", L + 1, k, {}, 0.});
    return more;
  }

  std::vector<StudyRun>
  ImpactConvergenceStudy::second_mesh_level(
    const ConvergedEpsilon &result) const
  {
    // d_t on the base mesh, from the split run: level 1 at the halved step
    // at once where 3 |d_t| alone fills the share of the target.
    const double d_t = find_run(result, 0, 1)->summary.epsilon -
                       result.runs.front().summary.epsilon;
    if (3. * std::abs(d_t) >= halve_first_above * target_error)
      return {{"mesh", 1, 1, {}, 0.}, {"split", 1, 1, {}, 0.}};
    return {{"mesh", 1, 0, {}, 0.}};
  }

  ConvergedEpsilon
  ImpactConvergenceStudy::run(const Parameters &given,
                              MPI_Comm          communicator,
                              std::ostream     *log) const
  {
    // Every rank measures the contact on its own: the same mesh on any
    // number of ranks.
    const Parameters parameters =
      with_mesh_graded_for_measured_contact(given, MPI_COMM_SELF);
    if (log != nullptr && given.impact.grades_for_measured_contact())
      *log << describe_measured_grading(parameters) << '\n';
    std::vector<StudyRun>             runs{{"base", 0, 0, {}, 0.}};
    std::vector<Parameters>           points{parameters};
    const std::array<unsigned int, 3> levels{
      {mesh_levels, time_step_levels, penalty_levels}};
    const bool halve_first = halve_first_above > 0.;
    for (unsigned int i = 0; i < levels.size(); ++i)
      for (unsigned int level = 1; level < levels[i]; ++level)
        {
          // With 'Halve first above' the second mesh level waits for the
          // split run.
          if (halve_first && factor_sequences[i].name == "mesh")
            continue;
          runs.push_back({factor_sequences[i].name, level, 0, {}, 0.});
          points.push_back(
            refined(parameters, factor_sequences[i].name, level));
        }
    if (separate_time_step && mesh_levels >= 2)
      {
        runs.push_back({"split", mesh_levels - 1, 0, {}, 0.});
        points.push_back(refined(parameters, "split", mesh_levels - 1));
      }
    if (log != nullptr)
      *log << "    factor   l   DoFs   dt [R/c]      epsilon   energy"
              " err.  time\n";

    ConvergedEpsilon result;
    SharedOperators  shared;
    auto             run_more = [&](const std::vector<StudyRun> &more) {
      std::vector<Parameters> more_points;
      for (const auto &run : more)
        more_points.push_back(
          refined(parameters, run.factor, run.level, run.time_halvings));
      const auto finer = run_all(more, more_points, communicator, log, shared);
      result.runs.insert(result.runs.end(), finer.begin(), finer.end());
    };
    result.runs = run_all(runs, points, communicator, log, shared);
    if (halve_first)
      run_more(second_mesh_level(result));
    estimate(result);
    // More runs while the bar exceeds the target (every rank sees the same
    // bar, so all take the same decision).
    while (target_error > 0. && result.error > target_error)
      {
        const auto more = next_refinement(result);
        if (more.empty())
          break;
        run_more(more);
        estimate(result);
      }
    return result;
  }

  CsvTable
  ImpactConvergenceStudy::runs_table(const ConvergedEpsilon &result)
  {
    CsvTable table({"factor",
                    "level",
                    "time_halvings",
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
        table.add(run.time_halvings);
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
    CsvTable table({"factor",
                    "observed_order",
                    "order_scatter",
                    "clean",
                    "limit",
                    "correction",
                    "error"});
    for (unsigned int i = 0; i < result.factors.size(); ++i)
      {
        const auto &e = result.estimates[i];
        table.start_row();
        table.add(result.factors[i]);
        table.add(e.order);
        table.add(e.order_scatter);
        table.add(e.clean ? 1 : 0);
        table.add(e.extrapolated);
        table.add(e.extrapolated - result.base.epsilon);
        table.add(e.error);
      }
    table.start_row();
    table.add(std::string("total"));
    table.add_empty();
    table.add_empty();
    table.add_empty();
    table.add(result.epsilon);
    table.add(result.epsilon - result.base.epsilon);
    table.add(result.error);
    return table;
  }

  std::string
  ImpactConvergenceStudy::describe(const StudyRun &run)
  {
    std::ostringstream line;
    // a level with further time step halvings as "level+halvings"
    const std::string level =
      std::to_string(run.level) +
      (run.time_halvings > 0 ? "+" + std::to_string(run.time_halvings) : "");
    line << std::setw(10) << run.factor << std::setw(4) << level << std::setw(7)
         << run.summary.n_dofs << std::setw(12) << std::scientific
         << std::setprecision(3) << run.summary.time_step << std::fixed
         << std::setprecision(8) << std::setw(13) << run.summary.epsilon
         << std::scientific << std::setprecision(1) << std::setw(10)
         << run.summary.energy_error << std::fixed << std::setprecision(1)
         << std::setw(8) << run.wall_time << " s\n";
    return line.str();
  }
} // namespace DiskImpact
