#include "tasks/modal_expansion_task.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "base/renamed_entries.h"
#include "base/run_error.h"
#include "output/csv_table.h"
#include "run/parameters.h"
#include "run/task_registry.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// One collision of the study.
    struct Run
    {
      double       nu2;
      double       v;
      double       alpha;
      unsigned int n_modes;
    };

    /// Numbers per run: epsilon, contact time, force, energy error, time
    /// step, steps, wall time, then per listed mode n, l, family, omega,
    /// energy after, average energy.
    constexpr unsigned int n_run_fields       = 7;
    constexpr unsigned int contact_time_field = 1;
    constexpr unsigned int n_mode_fields      = 6;

    const std::vector<Reference::ModeFamily> families{
      Reference::ModeFamily::rigid,
      Reference::ModeFamily::radial,
      Reference::ModeFamily::torsional,
      Reference::ModeFamily::mixed};

    /// Runs whose wall force never exceeded the contact threshold have no
    /// contact time (NaN, an empty cell): say how many.
    void
    report_runs_without_window(const std::vector<double> &fields,
                               const unsigned int         per_run,
                               const std::size_t          n_runs,
                               ConditionalOStream        &out)
    {
      unsigned int without = 0;
      for (std::size_t i = 0; i < n_runs; ++i)
        without += std::isnan(fields[per_run * i + contact_time_field]) ? 1 : 0;
      if (without > 0)
        out << "  " << without << " of " << n_runs
            << " runs had no contact window (the wall force stayed below "
            << 100. * Reference::ModalImpactConfig().contact_threshold
            << " % of the rigid disk's peak force): their contact_time and "
               "average_energy_fraction are left empty, and their modes are "
               "ranked by the energy after the collision\n";
    }

    std::vector<double>
    pack(const Reference::ModalImpactResult &r,
         const double                        seconds,
         const unsigned int                  mode_rows)
    {
      std::vector<double> values{r.epsilon,
                                 r.contact_time,
                                 r.max_force,
                                 r.energy_error,
                                 r.time_step,
                                 static_cast<double>(r.steps),
                                 seconds};
      // Ranked by the average over the contact; by the energy after it
      // where the run had no contact window (averages NaN).
      const bool window = std::isfinite(r.contact_time);
      auto       modes  = r.modes;
      std::sort(modes.begin(),
                modes.end(),
                [window](const auto &a, const auto &b) {
                  return window ? a.average_energy > b.average_energy :
                                  a.energy_after > b.energy_after;
                });
      modes.resize(std::min<std::size_t>(modes.size(), mode_rows));
      for (const auto &m : modes)
        for (const double value :
             {static_cast<double>(m.label.n),
              static_cast<double>(m.label.l),
              static_cast<double>(
                std::find(families.begin(), families.end(), m.label.family) -
                families.begin()),
              m.omega,
              m.energy_after,
              m.average_energy})
          values.push_back(value);
      values.resize(n_run_fields + n_mode_fields * mode_rows, -1.);
      return values;
    }

    using CaseMap =
      std::map<std::vector<double>, std::vector<std::pair<double, double>>>;

    /**
     * Gerl & Zippelius' extrapolations: for each (nu2, v, alpha) epsilon(N) to
     * N -> infinity, linear in 1 / sqrt(N); then those limits to
     * alpha -> infinity, linear in 1 / alpha, with the error bar of that fit
     * plus the largest of the N fits'. Writes modal_extrapolation.csv and
     * prints the hard-contact limits.
     */
    void
    write_extrapolation(const CaseMap      &by_case,
                        const std::string  &filename,
                        ConditionalOStream &out)
    {
      CsvTable table({"poisson_ratio_2d",
                      "velocity",
                      "potential_stiffness",
                      "limit",
                      "epsilon",
                      "slope",
                      "residual",
                      "error"});
      auto     add_row = [&](const double               nu2,
                         const double               v,
                         const double               alpha,
                         const std::string         &limit,
                         const LinearExtrapolation &fit) {
        table.start_row();
        for (const double value : {nu2, v, alpha})
          table.add(value);
        table.add(limit);
        for (const double value :
             {fit.limit, fit.slope, fit.residual, fit.error})
          table.add(value);
        out << std::fixed << std::setprecision(3) << std::setw(7) << nu2
            << std::setw(8) << v << std::setprecision(0) << std::setw(8)
            << alpha << std::setw(11) << limit << std::setprecision(5)
            << std::setw(11) << fit.limit << std::setw(11) << fit.slope
            << std::scientific << std::setprecision(1) << std::setw(10)
            << fit.residual << std::setw(10) << fit.error << '\n';
      };
      out << "Fits epsilon = limit + slope x: x = 1/sqrt(N) for each wall "
             "stiffness s (N -> infinity), then x = 1/s (hard contact, s = "
             "inf):\n"
             "    nu2     v/c       s      limit    epsilon      slope  "
             "residual     error\n";
      // (nu2, v) -> (1 / alpha, epsilon_N->inf, its error)
      std::map<std::pair<double, double>, std::vector<std::array<double, 3>>>
        per_velocity;
      for (const auto &[key, points] : by_case)
        {
          std::vector<double> x, y;
          for (const auto &[n, epsilon] : points)
            {
              x.push_back(1. / std::sqrt(n));
              y.push_back(epsilon);
            }
          LinearExtrapolation fit;
          if (points.size() >= 2)
            fit = extrapolate_linearly(x, y);
          else
            fit = {y[0], 0., 0., std::nan("")};
          add_row(key[0], key[1], key[2], "modes", fit);
          per_velocity[{key[0], key[1]}].push_back(
            {{1. / key[2], fit.limit, fit.error}});
        }
      for (const auto &[key, points] : per_velocity)
        {
          if (points.size() < 2)
            continue;
          std::vector<double> x, y;
          double              mode_error = 0.;
          for (const auto &[inverse_alpha, epsilon, error] : points)
            {
              x.push_back(inverse_alpha);
              y.push_back(epsilon);
              mode_error = std::max(mode_error, error);
            }
          LinearExtrapolation fit = extrapolate_linearly(x, y);
          fit.error += mode_error;
          add_row(key.first,
                  key.second,
                  std::numeric_limits<double>::infinity(),
                  "stiffness",
                  fit);
        }
      table.write(filename);
    }
  } // namespace

  void
  ModalExpansionStudy::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal expansion");
    prm.declare_entry("Velocities",
                      "0.1",
                      Patterns::List(Patterns::Double(0.), 1),
                      "Impact speeds v / c [-].");
    prm.declare_entry(
      "Potential stiffnesses",
      "100, 200, 500",
      Patterns::List(Patterns::Double(0.), 1),
      "Stiffnesses s of the wall potential (E2 R / s) exp(s x / R) per "
      "unit edge length (Gerl & Zippelius 1999, eq. 41, who call it "
      "alpha) [-]; with two or more, epsilon is extrapolated to hard "
      "contact (linear in 1 / s).");
    prm.declare_entry("Mode counts",
                      "100, 200, 400, 800, 1600",
                      Patterns::List(Patterns::Integer(1), 1),
                      "Numbers N of the lowest free-disk modes symmetric "
                      "about the impact axis [-]; with two or more, epsilon "
                      "is extrapolated to N -> infinity (linear in "
                      "1 / sqrt(N)).");
    prm.declare_entry("In-plane Poisson ratios",
                      "",
                      Patterns::List(Patterns::Double(), 0),
                      "In-plane Poisson ratios nu2 [-] (plane strain with "
                      "the 3D nu has nu2 = nu / (1 - nu)); empty: the "
                      "in-plane ratio of subsection Material.");
    prm.declare_entry("Angular points",
                      "256",
                      Patterns::Integer(2),
                      "Trapezoidal points on the quarter of the edge facing "
                      "the wall [-].");
    prm.declare_entry("Steps per period",
                      "40",
                      Patterns::Double(2.),
                      "Time steps per 2 pi / max(omega_N, s v / R) [-].");
    prm.declare_entry(
      "Integrator",
      "runge kutta",
      Patterns::Selection("runge kutta|splitting"),
      "'runge kutta': RK4 on the interaction-picture "
      "amplitudes (Gerl & Zippelius 1999, eq. 44 corrected); 'splitting': "
      "symplectic Strang splitting, each oscillator rotated "
      "exactly (docs/theory/modal-expansion-model.md).");
    prm.declare_entry("Number of listed modes",
                      "10",
                      Patterns::Integer(0, 100),
                      "Modes listed in modal_expansion_modes.csv per run "
                      "with the largest N, by average energy during the "
                      "collision (by the energy after it where the run had "
                      "no contact window) [-].");
    declare_renamed_entry(prm,
                          "Modal expansion",
                          "In-plane Poisson ratios",
                          "Poisson ratios");
    declare_renamed_entry(prm,
                          "Modal expansion",
                          "Number of listed modes",
                          "Mode energies");
    prm.leave_subsection();
  }

  void
  ModalExpansionStudy::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal expansion");
    velocities       = get_double_list(prm, "Velocities");
    alphas           = get_double_list(prm, "Potential stiffnesses");
    poisson_ratios   = get_double_list(prm, "In-plane Poisson ratios");
    mode_counts      = get_count_list(prm, "Mode counts");
    angular_points   = prm.get_integer("Angular points");
    steps_per_period = prm.get_double("Steps per period");
    integrator       = prm.get("Integrator") == "splitting" ?
                         Reference::ModalIntegrator::strang_splitting :
                         Reference::ModalIntegrator::runge_kutta_interaction_picture;
    mode_rows        = prm.get_integer("Number of listed modes");
    prm.leave_subsection();
    require_each(
      velocities,
      [](const double v) { return v > 0. && v < 1.; },
      "Modal expansion: every entry of 'Velocities' must satisfy 0 < v/c < 1");
    require_each(
      alphas,
      [](const double a) { return a > 0.; },
      "Modal expansion: every entry of 'Potential stiffnesses' must be "
      "positive");
    require_each(
      poisson_ratios,
      [](const double nu2) { return nu2 > -1. && nu2 < 1.; },
      "Modal expansion: every entry of 'In-plane Poisson ratios' must satisfy "
      "-1 < nu2 < 1");
  }

  void
  ModalExpansionStudy::run(const Parameters &parameters,
                           MPI_Comm          communicator) const
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    ConditionalOStream pcout(std::cout, rank == 0);

    std::vector<double> ratios = poisson_ratios;
    if (ratios.empty())
      ratios.push_back(parameters.material.in_plane_poisson_ratio());
    const unsigned int largest_n =
      *std::max_element(mode_counts.begin(), mode_counts.end());
    std::vector<Run> runs;
    for (const double nu2 : ratios)
      for (const double v : velocities)
        for (const double alpha : alphas)
          for (const unsigned int n : mode_counts)
            runs.push_back({nu2, v, alpha, n});

    // Round robin over the ranks; each rank builds the mode shapes of the
    // Poisson ratios it needs once, for the largest N.
    const unsigned int  per_run = n_run_fields + n_mode_fields * mode_rows;
    std::vector<double> fields(per_run * runs.size(), 0.);
    std::map<double, std::vector<Reference::FreeDiskModeShape>> bases;
    pcout << "    nu2     v/c       s      N      epsilon   energy err."
             "   time\n";
    // A run that fails on one rank fails the task on all.
    collectively(communicator, [&]() {
      for (unsigned int i = rank; i < runs.size(); i += n_ranks)
        {
          const Run &run = runs[i];
          if (bases.count(run.nu2) == 0)
            {
              const auto start = std::chrono::steady_clock::now();
              bases[run.nu2] =
                Reference::symmetric_mode_shapes(run.nu2, largest_n);
              pcout << "  " << largest_n << " mode shapes for nu2 = " << run.nu2
                    << ": "
                    << std::chrono::duration<double>(
                         std::chrono::steady_clock::now() - start)
                         .count()
                    << " s\n";
            }
          Reference::ModalImpactConfig config;
          config.in_plane_poisson_ratio = run.nu2;
          config.velocity               = run.v;
          config.alpha                  = run.alpha;
          config.n_modes                = run.n_modes;
          config.angular_points         = angular_points;
          config.steps_per_period       = steps_per_period;
          config.integrator             = integrator;
          const auto start              = std::chrono::steady_clock::now();
          const auto result =
            Reference::ModalExpansionImpact(config, bases[run.nu2]).run();
          const double seconds = std::chrono::duration<double>(
                                   std::chrono::steady_clock::now() - start)
                                   .count();
          if (!result.separated)
            throw std::runtime_error(
              "modal expansion: the disk did not leave the wall within the "
              "time limit (nu2 = " +
              Utilities::to_string(run.nu2) +
              ", v = " + Utilities::to_string(run.v) +
              ", s = " + Utilities::to_string(run.alpha) +
              ", N = " + Utilities::to_string(run.n_modes) +
              "); more 'Steps per period' may help");
          const auto values = pack(result, seconds, mode_rows);
          std::copy(values.begin(), values.end(), &fields[per_run * i]);
          pcout << std::fixed << std::setprecision(3) << std::setw(7) << run.nu2
                << std::setw(8) << run.v << std::setprecision(0) << std::setw(8)
                << run.alpha << std::setw(7) << run.n_modes
                << std::setprecision(7) << std::setw(13) << result.epsilon
                << std::scientific << std::setprecision(1) << std::setw(12)
                << result.energy_error << std::fixed << std::setprecision(1)
                << std::setw(7) << seconds << " s\n"
                << std::flush;
        }
    });
    Utilities::MPI::sum(fields, communicator, fields);
    on_root(communicator, [&]() {
      const std::string directory = parameters.run.output_directory + "/";
      CsvTable          table({"poisson_ratio_2d",
                               "velocity",
                               "potential_stiffness",
                               "n_modes",
                               "epsilon",
                               "contact_time",
                               "force_max",
                               "energy_error",
                               "time_step",
                               "steps",
                               "wall_time"});
      CsvTable          modes({"poisson_ratio_2d",
                               "velocity",
                               "potential_stiffness",
                               "n_modes",
                               "rank",
                               "n",
                               "l",
                               "family",
                               "omega",
                               "energy_fraction",
                               "average_energy_fraction"});
      CaseMap           by_case; // (nu2, v, alpha) -> (N, epsilon)
      for (unsigned int i = 0; i < runs.size(); ++i)
        {
          const Run    &run = runs[i];
          const double *f   = &fields[per_run * i];
          table.start_row();
          for (const double value : {run.nu2, run.v, run.alpha})
            table.add(value);
          table.add(run.n_modes);
          for (unsigned int k = 0; k < n_run_fields; ++k)
            table.add(f[k]);
          by_case[{run.nu2, run.v, run.alpha}].emplace_back(run.n_modes, f[0]);
          if (run.n_modes != largest_n)
            continue;
          for (unsigned int m = 0; m < mode_rows; ++m)
            {
              const double *mode = f + n_run_fields + n_mode_fields * m;
              if (mode[0] < 0.)
                break;
              modes.start_row();
              for (const double value : {run.nu2, run.v, run.alpha})
                modes.add(value);
              modes.add(run.n_modes);
              modes.add(m + 1);
              modes.add(static_cast<unsigned int>(mode[0]));
              modes.add(static_cast<unsigned int>(mode[1]));
              modes.add(
                to_string(families[static_cast<unsigned int>(mode[2])]));
              for (unsigned int k = 3; k < n_mode_fields; ++k)
                modes.add(mode[k]);
            }
        }
      report_runs_without_window(fields, per_run, runs.size(), pcout);
      table.write(directory + "modal_expansion.csv");
      modes.write(directory + "modal_expansion_modes.csv");
      write_extrapolation(by_case,
                          directory + "modal_extrapolation.csv",
                          pcout);
    });
  }

  namespace
  {
    TaskEntry
    modal_expansion_task()
    {
      TaskEntry task;
      task.name          = "modal expansion impact";
      task.description   = "the impact in the modal expansion of Gerl & "
                           "Zippelius 1999 with its smooth wall potential, "
                           "extrapolated to all modes and hard contact "
                           "(subsection Modal expansion, modal_expansion.csv, "
                           "modal_extrapolation.csv).";
      task.traits.meshes = false;
      task.traits.sphere = false;
      task.result_files  = {"modal_expansion.csv",
                            "modal_expansion_modes.csv",
                            "modal_extrapolation.csv"};
      add_own_parameters<ModalExpansionStudy>(task);
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        parameters.task_parameters<ModalExpansionStudy>().run(parameters,
                                                              communicator);
      };
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(modal_expansion_task())
} // namespace DiskImpact
