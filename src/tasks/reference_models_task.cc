#include "tasks/reference_models_task.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "base/renamed_entries.h"
#include "base/run_error.h"
#include "impact/impact_estimates.h"
#include "output/csv_table.h"
#include "reference/collision_ode.h"
#include "reference/linear_dashpot.h"
#include "reference/rayleigh_vibration.h"
#include "reference/schwager_disk.h"
#include "reference/viscoelastic_spheres.h"
#include "run/parameters.h"
#include "run/task_registry.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The 1-DOF disk collision in units E2 = rho = R = 1 (m = pi, c = 1,
    /// A = alpha); NaN where the log law cannot stop the disk (Schwager 2007,
    /// eq. 50: the scaled velocity beyond 1 / (sqrt(2) e)).
    Reference::Collision
    disk_collision(const double                  v,
                   const double                  alpha,
                   const double                  constant,
                   const Reference::EndCriterion end)
    {
      if (!(Reference::schwager_scaled_velocity(v, constant) <
            Reference::schwager_maximum_scaled_velocity()))
        {
          const double nan = std::nan("");
          return {nan, nan, nan};
        }
      return Reference::collide(
        M_PI, v, Reference::disk_force_law(1., 1., constant), alpha, end);
    }

    /// The (2,0) mode's share of Rayleigh's first-order vibration.
    double
    quadrupole_fraction(const Reference::RayleighVibration &vibration)
    {
      for (const auto &mode : vibration.modes)
        if (mode.label.n == 2 && mode.label.l == 0 &&
            mode.label.family == Reference::ModeFamily::mixed)
          return mode.energy_fraction;
      return 0.;
    }

    /// Rayleigh's model with feedback; NaN where the modes' quasistatic
    /// compliance exceeds the log law's at the collision's force (more
    /// modes than the contact width allows).
    Reference::RayleighImpact
    rayleigh_feedback(const double                                     v,
                      const double                                     C,
                      const double                                     nu2,
                      const std::vector<Reference::FreeDiskModeShape> &shapes)
    {
      try
        {
          return Reference::rayleigh_impact(v, C, nu2, shapes);
        }
      catch (const Reference::TooManyModes &)
        {
          const double nan = std::nan("");
          return {nan, nan, nan, nan, nan};
        }
    }

    /// @p formula(v_s) where the scaled velocity v_s is below the largest
    /// the log law allows (Schwager 2007, eq. 50); NaN beyond.
    template <typename Formula>
    double
    within_law(const double scaled_velocity, const Formula &formula)
    {
      return scaled_velocity < Reference::schwager_maximum_scaled_velocity() ?
               formula(scaled_velocity) :
               std::nan("");
    }
  } // namespace

  void
  ReferenceModels::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference models");
    prm.declare_entry(
      "Model",
      "disk",
      Patterns::Selection("disk|dashpot|spheres|rayleigh"),
      "Task 'reference models': 'disk' (log law with "
      "Kelvin-Voigt dissipation, Schwager 2007), 'dashpot' (linear "
      "spring and dashpot, Schwager & Pöschel 2007), 'spheres' "
      "(viscoelastic Hertz spheres, Ramírez et al. 1999) or 'rayleigh' "
      "(vibration left in the free-disk modes by the "
      "quasistatic collision of an elastic disk, Gerl & Zippelius 1999, "
      "eqs. 62-68).");
    prm.declare_entry("Velocities",
                      "0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1",
                      Patterns::List(Patterns::Double(0.), 1),
                      "Models 'disk' and 'rayleigh': impact speeds v / c "
                      "[-].");
    prm.declare_entry("Relaxation times",
                      "0.02, 0.05, 0.1",
                      Patterns::List(Patterns::Double(0.), 1),
                      "Model 'disk': Kelvin-Voigt relaxation times tau in "
                      "units of R/c [-], which equal Schwager's damping "
                      "parameter alpha = A sqrt(pi E2 / m) = tau c / R (A = "
                      "tau).");
    prm.declare_entry("Damping ratios",
                      "0.05, 0.2, 0.5, 0.7, 0.8, 0.9, 1, 1.5, 3, 10",
                      Patterns::List(Patterns::Double(0.), 1),
                      "Model 'dashpot': beta / omega0 [-].");
    prm.declare_entry(
      "Velocity ratios",
      "1e-8, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1, 10, 100",
      Patterns::List(Patterns::Double(0.), 1),
      "Model 'spheres': g / g* (Ramírez et al. 1999, eq. 30) [-].");
    prm.declare_entry("Mode counts",
                      "10, 25, 50, 100, 200",
                      Patterns::List(Patterns::Integer(1), 1),
                      "Model 'rayleigh': numbers N of the lowest free-disk "
                      "modes symmetric about the impact axis [-].");
    declare_renamed_entry(prm,
                          "Reference models",
                          "Relaxation times",
                          "Alphas");
    prm.leave_subsection();
  }

  void
  ReferenceModels::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference models");
    const std::map<std::string, ReferenceModel> models{
      {"disk", ReferenceModel::disk},
      {"dashpot", ReferenceModel::dashpot},
      {"spheres", ReferenceModel::spheres},
      {"rayleigh", ReferenceModel::rayleigh}};
    model           = models.at(prm.get("Model"));
    velocities      = get_double_list(prm, "Velocities");
    alphas          = get_double_list(prm, "Relaxation times");
    damping_ratios  = get_double_list(prm, "Damping ratios");
    velocity_ratios = get_double_list(prm, "Velocity ratios");
    mode_counts     = get_count_list(prm, "Mode counts");
    prm.leave_subsection();
    auto positive = [](const double x) { return x > 0.; };
    for (const auto &[entry, values] :
         {std::make_pair("Velocities", &velocities),
          std::make_pair("Damping ratios", &damping_ratios),
          std::make_pair("Velocity ratios", &velocity_ratios)})
      require_each(*values,
                   positive,
                   std::string("Reference models: every entry of '") + entry +
                     "' must be positive");
  }

  void
  ReferenceModels::check_velocities(const double law_constant) const
  {
    if (model != ReferenceModel::rayleigh)
      return;
    for (const double v : velocities)
      require(Reference::schwager_scaled_velocity(v, law_constant) <
                Reference::schwager_maximum_scaled_velocity(),
              "Reference models: an entry of 'Velocities', v/c = " +
                approximately(v, 6) +
                ", is too fast for the log law (Schwager 2007, eq. 50)");
  }

  void
  ReferenceModels::run(const Parameters &parameters,
                       MPI_Comm          communicator) const
  {
    // The models are cheap: rank 0 computes and writes them all.
    on_root(communicator, [&]() { tabulate(parameters); });
  }

  namespace
  {
    /// The table of @p model in its output directory.
    std::string
    table_name(const ReferenceModel model)
    {
      switch (model)
        {
          case ReferenceModel::disk:
            return "reference_disk.csv";
          case ReferenceModel::dashpot:
            return "reference_dashpot.csv";
          case ReferenceModel::spheres:
            return "reference_spheres.csv";
          case ReferenceModel::rayleigh:
            return "reference_rayleigh.csv";
        }
      return "";
    }
  } // namespace

  std::vector<std::string>
  ReferenceModels::other_models_files() const
  {
    std::vector<std::string> others;
    for (const auto other : {ReferenceModel::disk,
                             ReferenceModel::dashpot,
                             ReferenceModel::spheres,
                             ReferenceModel::rayleigh})
      if (other != model)
        others.push_back(table_name(other));
    return others;
  }

  void
  ReferenceModels::tabulate(const Parameters &parameters) const
  {
    const std::string file =
      parameters.run.output_directory + "/" + table_name(model);
    switch (model)
      {
        case ReferenceModel::disk:
          tabulate_disk(parameters, file);
          break;
        case ReferenceModel::dashpot:
          tabulate_dashpot(file);
          break;
        case ReferenceModel::spheres:
          tabulate_spheres(file);
          break;
        case ReferenceModel::rayleigh:
          tabulate_rayleigh(parameters, file);
          break;
      }
  }

  void
  ReferenceModels::tabulate_disk(const Parameters  &parameters,
                                 const std::string &filename) const
  {
    const double nu2 = parameters.material.in_plane_poisson_ratio();
    const double C   = one_dof_law_constant(parameters);
    const Reference::SchwagerDiskRestitution schwager;
    std::cout << "Disk: log law with C = " << C << " (nu2 = " << nu2
              << "): epsilon of the 1-DOF ODE (force and overlap end) and "
                 "eqs. 56, 80 of Schwager 2007\n"
              << "    v/c   alpha   force end   overlap end       eq. 56"
                 "       eq. 80\n";
    CsvTable table({"velocity",
                    "alpha",
                    "scaled_velocity",
                    "epsilon_ode",
                    "epsilon_ode_overlap",
                    "epsilon_first_order",
                    "epsilon_second_order",
                    "contact_time",
                    "delta_max"});
    for (const double alpha : alphas)
      for (const double v : velocities)
        {
          const auto force =
            disk_collision(v, alpha, C, Reference::EndCriterion::force);
          const auto overlap =
            disk_collision(v, alpha, C, Reference::EndCriterion::overlap);
          const double v_s    = Reference::schwager_scaled_velocity(v, C);
          const double first  = within_law(v_s, [&](const double speed) {
            return schwager.first_order(alpha, speed);
          });
          const double second = within_law(v_s, [&](const double speed) {
            return schwager.second_order(alpha, speed);
          });
          table.start_row();
          for (const double value : {v,
                                     alpha,
                                     v_s,
                                     force.epsilon,
                                     overlap.epsilon,
                                     first,
                                     second,
                                     force.contact_time,
                                     force.max_overlap})
            table.add(value);
          std::cout << std::fixed << std::setprecision(4) << std::setw(7) << v
                    << std::setw(8) << alpha << std::setprecision(7);
          for (const double epsilon :
               {force.epsilon, overlap.epsilon, first, second})
            std::cout << std::setw(13) << epsilon;
          std::cout << '\n';
        }
    table.write(filename);
  }

  void
  ReferenceModels::tabulate_dashpot(const std::string &filename) const
  {
    std::cout << "Linear dashpot: epsilon(beta / omega0)\n"
              << "  beta/omega0   eq. 21        ODE           overlap end\n";
    CsvTable table({"damping_ratio",
                    "epsilon",
                    "epsilon_ode",
                    "epsilon_overlap_criterion",
                    "epsilon_printed"});
    for (const double ratio : damping_ratios)
      {
        const double epsilon = Reference::dashpot_restitution(ratio, 1.);
        const double ode =
          Reference::dashpot_collision(ratio,
                                       1.,
                                       Reference::EndCriterion::force)
            .epsilon;
        const double overlap =
          Reference::dashpot_restitution_overlap_criterion(ratio, 1.);
        // The printed middle branch exists only on that branch.
        const bool   middle = ratio >= M_SQRT1_2 && ratio < 1.;
        const double printed =
          middle ?
            Reference::dashpot_restitution_printed_middle_branch(ratio, 1.) :
            epsilon;
        table.start_row();
        table.add(ratio);
        table.add(epsilon);
        table.add(ode);
        table.add(overlap);
        table.add(printed);
        std::cout << std::fixed << std::setprecision(4) << std::setw(11)
                  << ratio << std::setprecision(10) << std::setw(14) << epsilon
                  << std::setw(14) << ode << std::setw(14) << overlap << '\n';
      }
    table.write(filename);
  }

  void
  ReferenceModels::tabulate_spheres(const std::string &filename) const
  {
    using Reference::EndCriterion;
    std::cout << "Viscoelastic Hertz spheres: epsilon(g / g*)\n"
              << "    g/g*      ODE (force)  ODE (overlap)  series eq. 32"
                 "  Pade eq. 35\n";
    CsvTable    table({"velocity_ratio",
                       "scaled_velocity",
                       "epsilon_ode",
                       "epsilon_ode_overlap",
                       "epsilon_series",
                       "epsilon_series_force",
                       "epsilon_series_printed",
                       "epsilon_pade",
                       "epsilon_pade_printed"});
    const auto &printed = Reference::printed_sphere_coefficients;
    for (const double ratio : velocity_ratios)
      {
        // Ramírez et al.'s expansion variable (g / g*)^(1/5) (eq. 32).
        const double              u = std::pow(ratio, 0.2);
        const std::vector<double> row{
          ratio,
          u,
          Reference::sphere_restitution_ode(u, EndCriterion::force),
          Reference::sphere_restitution_ode(u, EndCriterion::overlap),
          Reference::sphere_restitution_series(u, EndCriterion::overlap),
          Reference::sphere_restitution_series(u, EndCriterion::force),
          Reference::sphere_restitution_series(u,
                                               EndCriterion::overlap,
                                               printed),
          Reference::sphere_restitution_pade(u),
          Reference::sphere_restitution_pade(u, printed)};
        table.start_row();
        for (const double value : row)
          table.add(value);
        std::cout << std::scientific << std::setprecision(2) << std::setw(10)
                  << ratio << std::fixed << std::setprecision(7);
        for (const unsigned int k : {2, 3, 4, 7})
          std::cout << std::setw(14) << row[k];
        std::cout << '\n';
      }
    table.write(filename);
  }

  void
  ReferenceModels::tabulate_rayleigh(const Parameters  &parameters,
                                     const std::string &filename) const
  {
    const double       nu2 = parameters.material.in_plane_poisson_ratio();
    const double       C   = one_dof_law_constant(parameters);
    const unsigned int largest =
      *std::max_element(mode_counts.begin(), mode_counts.end());
    std::cout << "Rayleigh: vibration left by the collision, log law with C = "
              << C << " (nu2 = " << nu2 << "), up to " << largest << " modes\n"
              << "  first order: the 1-DOF force on the modes (Gerl & "
                 "Zippelius 1999, eqs. "
                 "62-68); feedback: the\n  contact force also feels the "
                 "modes' dynamic displacement ('-': too many modes for\n  the "
                 "contact width)\n"
              << "    v/c       N   1-DOF t_c  vibration  (2,0) share   epsilon"
                 " | feedback: t_c    delta_max     epsilon  energy error\n";
    const auto all_shapes = Reference::symmetric_mode_shapes(nu2, largest);
    CsvTable   table({"velocity",
                      "modes",
                      "contact_time",
                      "delta_max",
                      "vibration_fraction",
                      "quadrupole_fraction",
                      "epsilon",
                      "contact_time_feedback",
                      "delta_max_feedback",
                      "vibration_fraction_feedback",
                      "epsilon_feedback",
                      "energy_error_feedback"});
    for (const double v : velocities)
      for (const unsigned int n : mode_counts)
        {
          const std::vector<Reference::FreeDiskModeShape> shapes(
            all_shapes.begin(), all_shapes.begin() + n);
          const auto first   = Reference::rayleigh_vibration(v, C, nu2, shapes);
          const auto coupled = rayleigh_feedback(v, C, nu2, shapes);
          const std::vector<double> row{v,
                                        double(n),
                                        first.contact_time,
                                        first.max_compression,
                                        first.vibration_fraction,
                                        quadrupole_fraction(first),
                                        first.epsilon(),
                                        coupled.contact_time,
                                        coupled.max_compression,
                                        coupled.vibration_fraction,
                                        coupled.epsilon,
                                        coupled.energy_error};
          table.start_row();
          for (const double value : row)
            table.add(value);
          std::cout << std::scientific << std::setprecision(1) << std::setw(8)
                    << v << std::setw(6) << n << std::fixed
                    << std::setprecision(5) << std::setw(11) << row[2]
                    << std::scientific << std::setprecision(3) << std::setw(11)
                    << row[4] << std::setw(11) << row[5] << std::fixed
                    << std::setprecision(6) << std::setw(11) << row[6] << " | ";
          if (std::isnan(coupled.epsilon))
            std::cout << std::setw(13) << '-';
          else
            std::cout << std::setprecision(5) << std::setw(13) << row[7]
                      << std::scientific << std::setprecision(5)
                      << std::setw(13) << row[8] << std::fixed
                      << std::setprecision(6) << std::setw(12) << row[10]
                      << std::scientific << std::setprecision(1)
                      << std::setw(10) << row[11];
          std::cout << std::endl;
        }
    table.write(filename);
  }

  namespace
  {
    TaskEntry
    reference_models_task()
    {
      TaskEntry task;
      task.name          = "reference models";
      task.description   = "epsilon of a reduced collision model of the disk, "
                           "no finite elements (subsection Reference models, "
                           "reference_<model>.csv).";
      task.traits.meshes = false;
      task.traits.sphere = false;
      task.result_files  = {"reference_*.csv"};
      add_own_parameters<ReferenceModels>(task);
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        parameters.task_parameters<ReferenceModels>().run(parameters,
                                                          communicator);
      };
      task.check = [](const Parameters &parameters) {
        parameters.task_parameters<ReferenceModels>().check_velocities(
          one_dof_law_constant(parameters));
      };
      task.kept_results = [](const Parameters &parameters) {
        return parameters.task_parameters<ReferenceModels>()
          .other_models_files();
      };
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(reference_models_task())
} // namespace DiskImpact
