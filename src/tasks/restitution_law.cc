#include "tasks/restitution_law.h"

#include "base/input_error.h"
#include "base/parameters.h"
#include "base/run_error.h"
#include "output/atomic_file.h"
#include "output/csv_table.h"
#include "reference/dem_contact_models.h"
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
    /// The sweep's results, in the run's dimensionless units.
    struct LawTable
    {
      std::vector<double> v, epsilon, error, contact_time, delta_max, force_max;
    };

    LawTable
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

    /// 1 - eps(v) = sum_{k=1}^{K} a_k (v / v_ref)^{k/5}: Hertz's scaling of
    /// the viscoelastic sphere's series (Ramírez et al. 1999), smooth for any
    /// body.
    struct SmoothFit
    {
      double              v_ref = 1.;
      std::vector<double> a;
      double
      operator()(const double v) const
      {
        const double x   = std::pow(v / v_ref, 0.2);
        double       sum = 0., power = 1.;
        for (const double coefficient : a)
          sum += coefficient * (power *= x);
        return 1. - sum;
      }
    };

    /// The weight of a point: 1 / its error bar (bars of zero or NaN, i.e.
    /// no error estimate, count as the median bar, or 1).
    std::vector<double>
    weights(const std::vector<double> &error)
    {
      std::vector<double> finite;
      for (const double e : error)
        if (e > 0. && std::isfinite(e))
          finite.push_back(e);
      std::sort(finite.begin(), finite.end());
      const double typical = finite.empty() ? 1. : finite[finite.size() / 2];
      std::vector<double> w;
      for (const double e : error)
        w.push_back(1. / (e > 0. && std::isfinite(e) ? e : typical));
      return w;
    }

    /// Weighted least squares for the a_k.
    SmoothFit
    fit_smooth(const LawTable &table, const double v_ref, unsigned int terms)
    {
      const unsigned int n = table.v.size();
      terms                = std::min<unsigned int>(terms, std::max(1u, n - 1));
      const auto         w = weights(table.error);
      FullMatrix<double> design(n, terms);
      Vector<double>     rhs(n), a(terms);
      for (unsigned int i = 0; i < n; ++i)
        {
          const double x     = std::pow(table.v[i] / v_ref, 0.2);
          double       power = 1.;
          for (unsigned int k = 0; k < terms; ++k)
            design(i, k) = w[i] * (power *= x);
          rhs[i] = w[i] * (1. - table.epsilon[i]);
        }
      Householder<double>(design).least_squares(a, rhs);
      return {v_ref, std::vector<double>(a.begin(), a.end())};
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
      return point.impact.estimate_collision(point).one_dof_epsilon;
    }

    struct DissipationFit
    {
      double              A = 0.;
      std::vector<double> epsilon; ///< the theory's, at each speed
    };

    /// A minimizing sum ((eps_theory - eps) / bar)^2 (Brent).
    DissipationFit
    fit_dissipation(const Parameters &parameters, const LawTable &table)
    {
      const auto w    = weights(table.error);
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

    /// y(x0) by linear interpolation in log x (clamped to the ends).
    double
    interpolate(const std::vector<double> &x,
                const std::vector<double> &y,
                const double               x0)
    {
      if (x0 <= x.front())
        return y.front();
      for (unsigned int i = 1; i < x.size(); ++i)
        if (x0 <= x[i])
          {
            const double s =
              std::log(x0 / x[i - 1]) / std::log(x[i] / x[i - 1]);
            return (1. - s) * y[i - 1] + s * y[i];
          }
      return y.back();
    }

    std::string
    number(const double value)
    {
      std::ostringstream text;
      text << std::setprecision(10) << value;
      return text.str();
    }

    std::string
    json_list(const std::vector<double> &values)
    {
      std::ostringstream text;
      text << std::setprecision(17) << '[';
      for (unsigned int i = 0; i < values.size(); ++i)
        text << (i > 0 ? ", " : "")
             << (std::isfinite(values[i]) ? number(values[i]) : "null");
      text << ']';
      return text.str();
    }

    /// What a DEM code needs, at the reference speed, in SI.
    struct DemInputs
    {
      double radius, density, young, poisson, mass, speed, epsilon,
        contact_time, liggghts_restitution, liggghts_epsilon, A, lammps_damping;
      Reference::LinearDashpotCollision yade; ///< ViscElMat's (en, tc)
    };

    std::map<std::string, std::string>
    dem_files(const DemInputs &d)
    {
      std::ostringstream head;
      head << "# diskimpact restitution law (SI units): a sphere of radius "
           << number(d.radius) << " m, density " << number(d.density)
           << " kg/m^3, E = " << number(d.young)
           << " Pa, nu = " << number(d.poisson)
           << ".\n# At the reference speed " << number(d.speed)
           << " m/s on a rigid wall (or two such spheres at relative speed "
           << number(2. * d.speed) << " m/s): epsilon = " << number(d.epsilon)
           << ", contact time " << number(d.contact_time) << " s.\n";
      std::map<std::string, std::string> files;
      files["liggghts.txt"] =
        head.str() +
        "# LIGGGHTS, model hertz: its damping keeps epsilon constant in v; "
        "coefficientRestitution\n# is the input for which LIGGGHTS' model "
        "gives epsilon = " +
        number(d.liggghts_epsilon) +
        ".\n# A wall must have a much larger youngsModulus to act as the "
        "rigid wall; 'hard_particles yes' allows E > 1e9 Pa.\n"
        "hard_particles yes\n"
        "fix m1 all property/global youngsModulus peratomtype " +
        number(d.young) +
        "\nfix m2 all property/global poissonsRatio peratomtype " +
        number(d.poisson) +
        "\nfix m3 all property/global coefficientRestitution peratomtypepair "
        "1 " +
        number(d.liggghts_restitution) +
        "\nfix m4 all property/global coefficientFriction peratomtypepair 1 "
        "0.0\npair_style gran model hertz tangential history\n"
        "pair_coeff * *\n";
      files["lammps.txt"] =
        head.str() +
        "# LAMMPS pair granular, Hertz with viscoelastic damping: Ramírez et "
        "al.'s "
        "law with the fitted A = " +
        number(d.A) +
        " s,\n# eta_n0 = 2 A E_eff / m_eff, the velocity dependence "
        "included.\npair_style granular\npair_coeff * * hertz/material " +
        number(d.young) + " " + number(d.lammps_damping) + " " +
        number(d.poisson) +
        " tangential linear_nohistory 0.0 0.0 damping viscoelastic\n";
      files["yade.py"] =
        "# Yade, ViscElMat (linear spring-dashpot from contact time and "
        "restitution)\n" +
        head.str() +
        "# ViscElMat's force is never attractive: its epsilon exceeds en "
        "and its contact time differs\n# from tc. These en, tc give the "
        "epsilon and contact time above, at every speed.\n"
        "mat = O.materials.append(ViscElMat(en=" +
        number(d.yade.epsilon) + ", et=0., tc=" + number(d.yade.contact_time) +
        ", density=" + number(d.density) + ", frictionAngle=0.))\n";
      files["mercurydpm.txt"] =
        "// MercuryDPM, LinearViscoelasticSpecies (particle-wall; for two "
        "such particles use mass / 2)\n" +
        std::regex_replace(head.str(), std::regex("(^|\n)# "), "$1// ") +
        "species.setDensity(" + number(d.density) +
        ");\nspecies.setCollisionTimeAndRestitutionCoefficient(" +
        number(d.contact_time) + ", " + number(d.epsilon) + ", " +
        number(d.mass) + ");\n";
      files["lethe.prm"] =
        head.str() +
        "# Lethe (lethe-particles), subsection lagrangian physical "
        "properties, particle type 0:\n"
        "set diameter                          = " +
        number(2. * d.radius) +
        "\nset density particles                 = " + number(d.density) +
        "\nset young modulus particles           = " + number(d.young) +
        "\nset poisson ratio particles           = " + number(d.poisson) +
        "\nset restitution coefficient particles = " + number(d.epsilon) + "\n";
      return files;
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
      const std::string   &directory = parameters.run.output_directory;
      const LawTable       table     = read_sweep(directory);
      const auto          &v         = table.v;
      const double         v_ref     = reference_speed > 0. ?
                                         reference_speed :
                                         std::sqrt(*std::min_element(v.begin(), v.end()) *
                                       *std::max_element(v.begin(), v.end()));
      const SmoothFit      smooth    = fit_smooth(table, v_ref, fit_terms);
      const DissipationFit theory    = fit_dissipation(parameters, table);
      const UnitSystem    &units     = parameters.units;
      const bool           sphere    = parameters.geometry.is_axisymmetric();

      // The table, dimensionless and in SI.
      std::vector<std::string> names{"velocity",
                                     "epsilon",
                                     "epsilon_error",
                                     "contact_time",
                                     "delta_max",
                                     "force_max",
                                     "epsilon_smooth_fit",
                                     "epsilon_theory_fit"};
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

      // The DEM inputs: a sphere, in SI.
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
            interpolate(v, table.contact_time, v_ref) * units.time();
          d.liggghts_restitution = Reference::liggghts_hertz_input(epsilon_ref);
          d.liggghts_epsilon =
            Reference::liggghts_hertz_epsilon(d.liggghts_restitution);
          d.A = theory.A * units.input_time();
          // E_eff and m_eff of the wall-equivalent pair: E* and m.
          d.lammps_damping = Reference::lammps_viscoelastic_damping(
            d.A, d.young / (1. - d.poisson * d.poisson), d.mass);
          d.yade = Reference::yade_viscel_inputs(d.epsilon, d.contact_time);
          files  = dem_files(d);
          dem_json << "{\"reference_speed_si\": " << number(d.speed)
                   << ", \"epsilon\": " << number(d.epsilon)
                   << ", \"contact_time_si\": " << number(d.contact_time)
                   << ", \"liggghts_coefficient_restitution\": "
                   << number(d.liggghts_restitution)
                   << ", \"yade_viscelmat_en\": " << number(d.yade.epsilon)
                   << ", \"yade_viscelmat_tc\": " << number(d.yade.contact_time)
                   << ", \"lammps_viscoelastic_eta_n0\": "
                   << number(d.lammps_damping)
                   << ", \"dissipative_constant_si\": " << number(d.A)
                   << ", \"files\": [\"dem/liggghts.txt\", \"dem/lammps.txt\", "
                      "\"dem/yade.py\", \"dem/mercurydpm.txt\", "
                      "\"dem/lethe.prm\"]}";
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
           << "\",\n  \"dimensionless_units\": \"" << Impact::units(parameters)
           << "\",\n";
      if (units.is_si())
        json << "  \"si_scales\": {\"R_m\": " << number(units.length())
             << ", \"c_m_per_s\": " << number(units.speed())
             << ", \"R_over_c_s\": " << number(units.time())
             << ", \"force_unit\": " << number(units.force())
             << ", \"force_unit_name\": \"" << units.force_name() << "\"},\n";
      json << "  \"table\": {\"velocity\": " << json_list(v)
           << ", \"epsilon\": " << json_list(table.epsilon)
           << ", \"epsilon_error\": " << json_list(table.error)
           << ", \"contact_time\": " << json_list(table.contact_time)
           << ", \"delta_max\": " << json_list(table.delta_max)
           << ", \"force_max\": " << json_list(table.force_max) << "},\n"
           << "  \"smooth_fit\": {\"form\": \"1 - sum_k a_k (v/v_ref)^(k/5)\", "
              "\"v_ref\": "
           << number(v_ref) << ", \"a\": " << json_list(smooth.a)
           << ", \"max_residual\": " << number(smooth_residual) << "},\n"
           << "  \"theory_fit\": {\"model\": \""
           << (sphere ? "Ramírez et al. 1999 (Brilliantov) with A" :
                        "Schwager 2007 (Schwager) with A")
           << "\", \"A\": " << number(theory.A) << ", \"relaxation_time\": "
           << number(parameters.material.relaxation_time())
           << ", \"time_unit\": \"R sqrt(rho/E)\""
           << (units.is_si() ?
                 ", \"A_si\": " + number(theory.A * units.input_time()) :
                 std::string())
           << ", \"max_residual\": " << number(theory_residual) << "},\n"
           << "  \"reference_speed\": " << number(v_ref)
           << ",\n  \"epsilon_at_reference_speed\": " << number(epsilon_ref)
           << ",\n  \"dem\": " << dem_json.str()
           << ",\n  \"parameters\": " << parameters.run.parameters_json
           << "\n}\n";
      write_atomically(directory + "/restitution_law.json", json.str());

      // The reference speed in the units of the parameter file.
      const std::string reference_speed =
        units.is_si() ? number(v_ref * units.speed()) + " m/s" :
                        number(v_ref) + " c";
      std::cout << "Restitution law: smooth fit 1 - eps = sum a_k (v / "
                << reference_speed << ")^{k/5}, a = " << json_list(smooth.a)
                << ", largest residual " << number(smooth_residual)
                << "\n  1-DOF theory fit: A = "
                << number(theory.A * (units.is_si() ? units.input_time() : 1.))
                << (units.is_si() ? " s" : " (units of 'Relaxation time')")
                << ", tau = "
                << number(parameters.material.relaxation_time() *
                          (units.is_si() ? units.input_time() : 1.))
                << (units.is_si() ? " s" : "") << ", largest residual "
                << number(theory_residual)
                << "\n  at v_ref = " << reference_speed
                << ": epsilon = " << number(epsilon_ref) << '\n';
      if (!files.empty())
        std::cout << "  DEM inputs in " << directory
                  << "/dem/ (LIGGGHTS, LAMMPS, Yade, MercuryDPM, Lethe)\n";
      else
        std::cout << "  DEM inputs: "
                  << (sphere ? "need 'Units = SI'" :
                               "written for spheres only (DEM codes are 3D)")
                  << '\n';
    });
  }
} // namespace DiskImpact
