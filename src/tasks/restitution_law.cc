#include "tasks/restitution_law.h"

#include "base/input_error.h"
#include "base/run_error.h"
#include "impact/impact_estimates.h"
#include "output/atomic_file.h"
#include "output/csv_table.h"
#include "reference/log_contact_law.h"
#include "reference/tangential_compliance.h"
#include "restitution/dem_inputs.h"
#include "restitution/restitution_fit.h"
#include "run/parameters.h"
#include "run/task_registry.h"
#include "tasks/sweep_task.h"

#include <deal.II/base/mpi.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/householder.h>
#include <deal.II/lac/vector.h>

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>

#ifndef DISKIMPACT_VERSION
#  define DISKIMPACT_VERSION "unknown"
#endif

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    std::string
    json_list(const std::vector<double> &values)
    {
      std::ostringstream text;
      text << std::setprecision(17) << '[';
      for (unsigned int i = 0; i < values.size(); ++i)
        text << (i > 0 ? ", " : "")
             << (std::isfinite(values[i]) ? ten_digits(values[i]) : "null");
      text << ']';
      return text.str();
    }

    RestitutionTable
    read_sweep(const std::string &directory)
    {
      const CsvTable sweep = CsvTable::read(directory + "/restitution.csv");
      return {sweep.column("velocity"),
              sweep.column("epsilon"),
              sweep.column("epsilon_error"),
              sweep.column("contact_time"),
              sweep.column("delta_max"),
              sweep.column("force_max")};
    }

    /// The papers' 1-DOF epsilon at speed @p v with dissipative constant A
    /// (the Kelvin-Voigt relaxation time,
    /// docs/theory/viscoelastic-spheres.md: A = tau).
    double
    theory_epsilon(const Parameters &parameters, const double v, const double A)
    {
      Parameters point = parameters;
      point.material   = parameters.material.with_relaxation_time(A);
      point.impact.set_velocity(v);
      return estimate_collision(point).one_dof_epsilon;
    }

    struct DissipationFit
    {
      double              A = 0.;
      std::vector<double> epsilon; ///< the theory's, at each speed
    };

    /// A minimizing sum ((eps_theory - eps) / bar)^2 (Brent).
    DissipationFit
    fit_dissipation(const Parameters &parameters, const RestitutionTable &table)
    {
      const auto w    = fit_weights(table.error);
      const auto chi2 = [&](const double A) {
        double sum = 0.;
        for (unsigned int i = 0; i < table.v.size(); ++i)
          sum += std::pow(w[i] * (theory_epsilon(parameters, table.v[i], A) -
                                  table.epsilon[i]),
                          2);
        return sum;
      };
      double upper = std::max(4. * parameters.material.relaxation_time(), 0.05);
      std::pair<double, double> best;
      for (unsigned int widen = 0; widen < 6; ++widen, upper *= 4.)
        {
          boost::uintmax_t iterations = 200;
          best                        = boost::math::tools::brent_find_minima(
            chi2, 0., upper, 40, iterations);
          if (best.first < 0.9 * upper)
            break;
        }
      DissipationFit fit{best.first, {}};
      for (const double v : table.v)
        fit.epsilon.push_back(theory_epsilon(parameters, v, fit.A));
      return fit;
    }

    /// A disk's DEM inputs at the reference speed @p v_ref (in units of
    /// c): a linear spring-dashpot with the FE's epsilon and contact time,
    /// the tangential spring with the disk's stiffness ratio at the largest
    /// contact half-width, per unit thickness in SI.
    DiskDemInputs
    disk_dem_inputs(const Parameters       &parameters,
                    const RestitutionTable &table,
                    const double            v_ref,
                    const double            epsilon_ref)
    {
      const UnitSystem &units    = parameters.units;
      const Material   &material = parameters.material;
      DiskDemInputs     d;
      d.radius  = units.length();
      d.density = units.density();
      d.young   = units.young_modulus();
      d.poisson = material.poisson_ratio();
      d.plane   = material.plane_model_name();
      d.mass    = d.density * M_PI * d.radius * d.radius;
      d.speed   = v_ref * units.speed();
      d.epsilon = epsilon_ref;
      d.contact_time =
        interpolate_in_log(table.v, table.contact_time, v_ref) * units.time();
      d.pair = Reference::linear_spring_dashpot(d.epsilon,
                                                d.contact_time,
                                                0.5 * d.mass);
      // The largest force, in units of E2 R, gives Hertz's half-width.
      const double force_max =
        interpolate_in_log(table.v, table.force_max, v_ref);
      d.half_width       = Reference::hertz_half_width(force_max / M_PI);
      d.tangential_ratio = Reference::disk_tangential_stiffness_ratio(
        d.half_width, material.in_plane_poisson_ratio());
      d.friction = parameters.contact.friction_coefficient();
      return d;
    }
  } // namespace

  void
  RestitutionLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Restitution law");
    prm.declare_entry("Reference speed",
                      "0",
                      Patterns::Double(0.),
                      "Speed at which the DEM inputs reproduce epsilon, in "
                      "units of c (m/s with 'Units = SI'); 0: the geometric "
                      "mean of the smallest and largest 'Velocities'.");
    prm.declare_entry("Fit terms",
                      "3",
                      Patterns::Integer(1, 6),
                      "Terms K of the smooth fit 1 - eps = sum_{k<=K} "
                      "a_k (v/v_ref)^{k/5} (at most the number of speeds "
                      "minus one).");
    prm.leave_subsection();
  }

  void
  RestitutionLaw::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Restitution law");
    reference_speed = prm.get_double("Reference speed");
    fit_terms       = prm.get_integer("Fit terms");
    prm.leave_subsection();
  }

  void
  RestitutionLaw::run(const Parameters &parameters,
                      const bool        resume,
                      MPI_Comm          communicator) const
  {
    // An earlier run's DEM inputs must not pass for this run's.
    on_root(communicator, [&]() {
      std::filesystem::remove_all(parameters.run.output_directory + "/dem");
    });
    run_sweep(parameters, resume, communicator);
    on_root(communicator, [&]() {
      const std::string     &directory = parameters.run.output_directory;
      const RestitutionTable table     = read_sweep(directory);
      const auto            &v         = table.v;
      const double           v_ref     = reference_speed > 0. ?
                                           reference_speed :
                                           std::sqrt(*std::min_element(v.begin(), v.end()) *
                                       *std::max_element(v.begin(), v.end()));
      const SmoothFit        smooth    = fit_smooth(table, v_ref, fit_terms);
      const DissipationFit   theory    = fit_dissipation(parameters, table);
      const UnitSystem      &units     = parameters.units;
      const bool             sphere    = parameters.geometry.is_sphere();
      const Material        &material  = parameters.material;
      // Thornton's elastic-plastic contact, for a plastic sphere.
      const bool        plastic_sphere = sphere && material.is_plastic();
      const ThorntonFit thornton =
        plastic_sphere ? fit_thornton(table,
                                      material.yield_stress() /
                                        material.in_plane_young_modulus()) :
                         ThorntonFit();
      // Luding's, Yade's elastic-plastic contact, likewise.
      const LudingFit luding = plastic_sphere ? fit_luding(table) : LudingFit();

      // A plastic sphere's fit of a contact model as JSON (else null).
      const auto plastic_fit_json = [&](const std::string         &model,
                                        const std::string         &fitted,
                                        const std::vector<double> &epsilon,
                                        const double               residual) {
        return plastic_sphere ?
                 "{\"model\": \"" + model + "\", " + fitted +
                   ", \"epsilon\": " + json_list(epsilon) +
                   ", \"max_residual\": " + ten_digits(residual) + "}" :
                 std::string("null");
      };

      // The table, dimensionless and in SI.
      std::vector<std::string> names{"velocity",
                                     "epsilon",
                                     "epsilon_error",
                                     "contact_time",
                                     "delta_max",
                                     "force_max",
                                     "epsilon_smooth_fit",
                                     "epsilon_theory_fit"};
      if (plastic_sphere)
        for (const std::string name :
             {"epsilon_thornton_fit", "epsilon_luding_fit"})
          names.push_back(name);
      if (units.is_si())
        for (const std::string name :
             {"speed_si", "contact_time_si", "delta_max_si", "force_max_si"})
          names.push_back(name);
      CsvTable            csv(names);
      std::vector<double> smooth_values, residuals;
      for (unsigned int i = 0; i < v.size(); ++i)
        {
          smooth_values.push_back(smooth(v[i]));
          csv.start_row();
          for (const double value : {v[i],
                                     table.epsilon[i],
                                     table.error[i],
                                     table.contact_time[i],
                                     table.delta_max[i],
                                     table.force_max[i],
                                     smooth_values[i],
                                     theory.epsilon[i]})
            csv.add(value);
          if (plastic_sphere)
            for (const double value : {thornton.epsilon[i], luding.epsilon[i]})
              csv.add(value);
          if (units.is_si())
            for (const double value : {v[i] * units.speed(),
                                       table.contact_time[i] * units.time(),
                                       table.delta_max[i] * units.length(),
                                       table.force_max[i] * units.force()})
              csv.add(value);
        }
      csv.write(directory + "/restitution_law.csv");
      double smooth_residual = 0., theory_residual = 0.;
      for (unsigned int i = 0; i < v.size(); ++i)
        {
          smooth_residual =
            std::max(smooth_residual,
                     std::abs(smooth_values[i] - table.epsilon[i]));
          theory_residual =
            std::max(theory_residual,
                     std::abs(theory.epsilon[i] - table.epsilon[i]));
        }

      // The DEM inputs, in SI: a sphere for 3D codes, a disk for 2D ones.
      std::map<std::string, std::string> files;
      std::ostringstream                 dem_json;
      const double                       epsilon_ref = smooth(v_ref);
      if (sphere && units.is_si())
        {
          DemInputs d;
          d.radius  = units.length();
          d.density = units.density();
          d.young   = units.young_modulus();
          d.poisson = parameters.material.poisson_ratio();
          d.mass    = d.density * 4. / 3. * M_PI * std::pow(d.radius, 3);
          d.speed   = v_ref * units.speed();
          d.epsilon = epsilon_ref;
          d.contact_time =
            interpolate_in_log(v, table.contact_time, v_ref) * units.time();
          d.liggghts_restitution = Reference::liggghts_hertz_input(epsilon_ref);
          d.liggghts_epsilon =
            Reference::liggghts_hertz_epsilon(d.liggghts_restitution);
          d.A = theory.A * units.input_time();
          // E_eff and m_eff of the wall-equivalent pair: E* and m.
          d.lammps_damping = Reference::lammps_viscoelastic_damping(
            d.A, d.young / (1. - d.poisson * d.poisson), d.mass);
          d.yade = Reference::yade_viscel_inputs(d.epsilon, d.contact_time);
          d.friction = parameters.contact.friction_coefficient();
          if (plastic_sphere)
            {
              d.limiting_pressure =
                thornton.pressure_ratio * material.yield_stress() *
                units.young_modulus() / material.young_modulus();
              d.yield_speed = thornton.yield_speed * units.speed();
              set_luding_inputs(d,
                                luding.stiffness_ratio,
                                luding.plastic_speed * units.speed());
            }
          files  = dem_files(d);
          dem_json << "{\"reference_speed_si\": " << ten_digits(d.speed)
                   << ", \"epsilon\": " << ten_digits(d.epsilon)
                   << ", \"contact_time_si\": " << ten_digits(d.contact_time)
                   << ", \"liggghts_coefficient_restitution\": "
                   << ten_digits(d.liggghts_restitution)
                   << ", \"yade_viscelmat_en\": " << ten_digits(d.yade.epsilon)
                   << ", \"yade_viscelmat_tc\": "
                   << ten_digits(d.yade.contact_time)
                   << ", \"lammps_viscoelastic_eta_n0\": "
                   << ten_digits(d.lammps_damping)
                   << ", \"friction_coefficient\": " << ten_digits(d.friction)
                   << ", \"dissipative_constant_si\": " << ten_digits(d.A);
          if (plastic_sphere)
            dem_json << ", \"liggghts_thornton_ning_yield_ratio\": "
                     << ten_digits(liggghts_yield_ratio(d))
                     << ", \"limiting_pressure_si\": "
                     << ten_digits(d.limiting_pressure)
                     << ", \"thornton_yield_speed_si\": "
                     << ten_digits(d.yield_speed)
                     << ", \"yade_luding_k1\": " << ten_digits(d.luding_k1)
                     << ", \"yade_luding_kp\": " << ten_digits(d.luding_kp)
                     << ", \"yade_luding_phi_f\": "
                     << ten_digits(d.luding_phi_f)
                     << ", \"luding_plastic_speed_si\": "
                     << ten_digits(d.luding_plastic_speed);
          dem_json << ", \"files\": [";
          for (auto file = files.begin(); file != files.end(); ++file)
            dem_json << (file == files.begin() ? "" : ", ") << "\"dem/"
                     << file->first << '"';
          dem_json << "]}";
        }
      else if (units.is_si())
        {
          const DiskDemInputs d =
            disk_dem_inputs(parameters, table, v_ref, epsilon_ref);
          files = dem_disk_files(d);
          dem_json << "{\"reference_speed_si\": " << ten_digits(d.speed)
                   << ", \"epsilon\": " << ten_digits(d.epsilon)
                   << ", \"contact_time_si\": " << ten_digits(d.contact_time)
                   << ", \"dimension\": 2, \"mass_per_thickness\": "
                   << ten_digits(d.mass)
                   << ", \"pair_stiffness\": " << ten_digits(d.pair.stiffness)
                   << ", \"pair_damping\": " << ten_digits(d.pair.damping)
                   << ", \"tangential_stiffness_ratio\": "
                   << ten_digits(d.tangential_ratio)
                   << ", \"contact_half_width\": " << ten_digits(d.half_width)
                   << ", \"friction_coefficient\": " << ten_digits(d.friction)
                   << ", \"files\": [\"dem/lammps_2d.txt\"]}";
        }
      else
        dem_json << "null";
      std::filesystem::create_directories(directory + "/dem");
      for (const auto &[name, text] : files)
        write_atomically(directory + "/dem/" + name, text);

      std::ostringstream json;
      json << std::setprecision(17) << "{\n  \"diskimpact_version\": \""
           << DISKIMPACT_VERSION << "\",\n  \"body\": \""
           << (sphere ? "sphere" : "disk") << "\",\n  \"units\": \""
           << (units.is_si() ? "SI" : "dimensionless")
           << "\",\n  \"dimensionless_units\": \"" << output_units(parameters)
           << "\",\n";
      if (units.is_si())
        json << "  \"si_scales\": {\"R_m\": " << ten_digits(units.length())
             << ", \"c_m_per_s\": " << ten_digits(units.speed())
             << ", \"R_over_c_s\": " << ten_digits(units.time())
             << ", \"force_unit\": " << ten_digits(units.force())
             << ", \"force_unit_name\": \"" << units.force_name() << "\"},\n";
      json << "  \"table\": {\"velocity\": " << json_list(v)
           << ", \"epsilon\": " << json_list(table.epsilon)
           << ", \"epsilon_error\": " << json_list(table.error)
           << ", \"contact_time\": " << json_list(table.contact_time)
           << ", \"delta_max\": " << json_list(table.delta_max)
           << ", \"force_max\": " << json_list(table.force_max) << "},\n"
           << "  \"smooth_fit\": {\"form\": \"1 - sum_k a_k (v/v_ref)^(k/5)\", "
              "\"v_ref\": "
           << ten_digits(v_ref) << ", \"a\": " << json_list(smooth.a)
           << ", \"max_residual\": " << ten_digits(smooth_residual) << "},\n"
           << "  \"theory_fit\": {\"model\": \""
           << (sphere ? "Ramírez et al. 1999 (Brilliantov) with A" :
                        "Schwager 2007 (Schwager) with A")
           << "\", \"A\": " << ten_digits(theory.A) << ", \"relaxation_time\": "
           << ten_digits(parameters.material.relaxation_time())
           << ", \"time_unit\": \"R sqrt(rho/E)\""
           << (units.is_si() ?
                 ", \"A_si\": " + ten_digits(theory.A * units.input_time()) :
                 std::string())
           << ", \"max_residual\": " << ten_digits(theory_residual) << "},\n"
           << "  \"thornton_fit\": "
           << plastic_fit_json("Thornton 1997 as LIGGGHTS' thornton_ning "
                               "without adhesion",
                               "\"limiting_pressure_over_yield_stress\": " +
                                 ten_digits(thornton.pressure_ratio) +
                                 ", \"yield_speed\": " +
                                 ten_digits(thornton.yield_speed),
                               thornton.epsilon,
                               thornton.max_residual)
           << ",\n  \"luding_fit\": "
           << plastic_fit_json(
                "Luding 2008 as Yade's LudingMat without "
                "adhesion",
                "\"stiffness_ratio\": " + ten_digits(luding.stiffness_ratio) +
                  ", \"plastic_speed\": " + ten_digits(luding.plastic_speed),
                luding.epsilon,
                luding.max_residual);
      json << ",\n"
           << "  \"reference_speed\": " << ten_digits(v_ref)
           << ",\n  \"epsilon_at_reference_speed\": " << ten_digits(epsilon_ref)
           << ",\n  \"dem\": " << dem_json.str()
           << ",\n  \"parameters\": " << parameters.run.parameters_json
           << "\n}\n";
      write_atomically(directory + "/restitution_law.json", json.str());

      // A speed in the units of the parameter file.
      const auto speed_text = [&](const double speed) {
        return units.is_si() ? ten_digits(speed * units.speed()) + " m/s" :
                               ten_digits(speed) + " c";
      };
      const std::string reference_speed = speed_text(v_ref);
      std::cout << "Restitution law: smooth fit 1 - eps = sum a_k (v / "
                << reference_speed << ")^{k/5}, a = " << json_list(smooth.a)
                << ", largest residual " << ten_digits(smooth_residual)
                << "\n  1-DOF theory fit: A = "
                << ten_digits(theory.A *
                              (units.is_si() ? units.input_time() : 1.))
                << (units.is_si() ? " s" : " (units of 'Relaxation time')")
                << ", tau = "
                << ten_digits(parameters.material.relaxation_time() *
                              (units.is_si() ? units.input_time() : 1.))
                << (units.is_si() ? " s" : "") << ", largest residual "
                << ten_digits(theory_residual)
                << "\n  at v_ref = " << reference_speed
                << ": epsilon = " << ten_digits(epsilon_ref) << '\n';
      if (plastic_sphere)
        std::cout << "  Thornton's model (LIGGGHTS' thornton_ning): p_y = "
                  << ten_digits(thornton.pressure_ratio)
                  << " Y, v_y = " << speed_text(thornton.yield_speed)
                  << ", largest residual " << ten_digits(thornton.max_residual)
                  << "\n  Luding's model (Yade's LudingMat): kp / k1 = "
                  << ten_digits(luding.stiffness_ratio)
                  << ", v_p = " << speed_text(luding.plastic_speed)
                  << ", largest residual " << ten_digits(luding.max_residual)
                  << '\n';
      if (files.empty())
        std::cout << "  DEM inputs: need 'Units = SI'\n";
      else
        std::cout << "  DEM inputs in " << directory
                  << (sphere ? "/dem/ (LIGGGHTS, LAMMPS, Yade, MercuryDPM, "
                               "Lethe)\n" :
                               "/dem/ (LAMMPS in 2D)\n");
    });
  }

  namespace
  {
    TaskEntry
    restitution_law_task()
    {
      TaskEntry task;
      task.name           = "restitution law";
      task.description    = "the sweep with its convergence studies, then "
                            "epsilon(v) fitted and stated as input for DEM "
                            "codes (subsection Restitution law; "
                            "restitution_law.csv, restitution_law.json, dem/).";
      task.traits.impacts = true;
      task.traits.sweeps  = true;
      task.traits.plasticity = true;
      task.traits.one_mesh_per_rank = true;
      task.traits.three_dimensional = true;
      task.result_files             = sweep_result_files();
      task.result_files.insert(task.result_files.end(),
                               {"restitution_law.csv", "restitution_law.json"});
      task.run = [](const Parameters &parameters,
                    const bool        resume,
                    MPI_Comm          communicator) {
        parameters.task_parameters<RestitutionLaw>().run(parameters,
                                                         resume,
                                                         communicator);
      };
      task.check                    = check_sweep;
      task.build_largest_mesh       = build_fastest_mesh<2>;
      task.build_largest_solid_mesh = build_fastest_mesh<3>;
      add_own_parameters<RestitutionLaw>(task);
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(restitution_law_task())
} // namespace DiskImpact
