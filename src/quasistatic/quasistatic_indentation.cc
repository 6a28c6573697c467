#include "quasistatic/quasistatic_indentation.h"

#include "base/run_error.h"
#include "output/atomic_file.h"
#include "output/csv_table.h"
#include "quasistatic/wall_contact_problem.h"
#include "run/parameters.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/petsc_vector.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The load at which Hertz's contact first yields: p0 grows as a power
    /// of the load (1/3 sphere, 1/2 disk), measured between two loads.
    double
    hertz_first_yield_load(const Parameters &parameters)
    {
      const auto theory =
        Reference::wall_contact_theory(parameters.geometry.is_axisymmetric());
      const double R  = parameters.geometry.radius();
      const double E2 = parameters.material.in_plane_young_modulus();
      auto         p0 = [&](const double load) {
        return theory->pressure(0., load) *
               theory->pressure_unit(load * theory->force_unit(E2, R), R);
      };
      const double l1 = 1e-6, l2 = 1e-4;
      const double exponent = std::log(p0(l2) / p0(l1)) / std::log(l2 / l1);
      const double p_yield  = hertz_first_yield(parameters).pressure_ratio *
                             parameters.material.yield_stress();
      return l1 * std::pow(p_yield / p0(l1), 1. / exponent);
    }

    /// The path: @p steps equal steps up to @p largest, as many down, and 0.
    std::vector<double>
    load_path(const double largest, const unsigned int steps)
    {
      std::vector<double> path;
      for (unsigned int k = 1; k <= steps; ++k)
        path.push_back(largest * k / steps);
      for (unsigned int k = steps; k-- > 0;)
        path.push_back(largest * k / steps);
      return path;
    }
  } // namespace

  void
  QuasistaticIndentation::run(const Parameters &parameters,
                              MPI_Comm          communicator) const
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(communicator) ==
                               0);
    const std::string &directory = parameters.run.output_directory;
    const double       R         = parameters.geometry.radius();
    const auto         theory =
      Reference::wall_contact_theory(parameters.geometry.is_axisymmetric());

    WallContactProblem<2> problem(parameters,
                                  largest_load / steps,
                                  largest_load,
                                  communicator);
    problem.enable_plasticity();
    // Energies in units of P_unit R, P_unit the force of load 1.
    const double energy_unit = problem.force(1.) * R;
    const double yield_load  = hertz_first_yield_load(parameters);

    CsvTable table({"step",
                    "load",
                    "delta_com",
                    "delta_diameter",
                    "half_width",
                    "penetration",
                    "force_balance_error",
                    "plastic_work",
                    "plastic_strain_max",
                    "energy_elastic",
                    "energy_contact",
                    "external_work",
                    "support_work",
                    "energy_error",
                    "newton_iterations"});
    std::vector<std::pair<double, std::string>> records;
    pcout << "Loading to " << largest_load << " and unloading in " << steps
          << " steps each; Hertz's contact first yields at load "
          << yield_load << "\n"
          << "  step      load     delta_com   a/R     alpha_max  "
             "plastic work  energy err.  Newton\n";

    const double a_first = theory->half_width(problem.get_load());
    problem.translate(0.5 * a_first * a_first);
    // The previous state's displacement, body force and support force
    // (contact, or the hold at load 0), from the undeformed body at rest.
    PETScWrappers::MPI::Vector u_old = problem.displacement(),
                               f_old = problem.body_force_vector(),
                               c_old = problem.support_force_vector();
    u_old = 0.;
    f_old = 0.;
    c_old = 0.;
    double work = 0., support_work = 0., plastic_work = 0.;
    double largest_work       = 0.;
    double last_elastic_load  = 0.;
    double first_plastic_load = std::numeric_limits<double>::quiet_NaN();
    double largest_error = 0., delta_max = 0.;
    const std::vector<double> path = load_path(largest_load, steps);
    for (unsigned int step = 0; step < path.size(); ++step)
      {
        problem.set_load(path[step]);
        const unsigned int iterations =
          problem.solve(tolerance, max_iterations);
        plastic_work += problem.accept();
        const auto [delta_com, delta_diameter] = problem.approach();
        const ContactState    state            = problem.contact_state();
        const double          elastic_energy   = problem.elastic_energy();
        const double          alpha = problem.largest_plastic_strain();

        // The work of the body force and of the support (wall or hold) by
        // the trapezoidal rule: with the plastic work's trapezoidal rule in
        // the stress, their difference is the elastic energy plus the
        // plastic work exactly (docs/theory/plasticity.md).
        PETScWrappers::MPI::Vector du = problem.displacement();
        du -= u_old;
        const PETScWrappers::MPI::Vector c = problem.support_force_vector();
        work += 0.5 * (f_old * du + problem.body_force_vector() * du) /
                problem.domain_share();
        support_work += 0.5 * (c_old * du + c * du) / problem.domain_share();
        u_old = problem.displacement();
        f_old = problem.body_force_vector();
        c_old = c;
        largest_work = std::max(largest_work, work);
        const double error =
          (work - support_work - elastic_energy - plastic_work) / largest_work;
        largest_error = std::max(largest_error, std::abs(error));
        delta_max     = std::max(delta_max, delta_com);
        if (alpha == 0.)
          last_elastic_load = path[step];
        else if (std::isnan(first_plastic_load))
          first_plastic_load = path[step];

        table.start_row();
        table.add(step + 1);
        const double force = problem.force(path[step]);
        for (const double v :
             {path[step],
              delta_com,
              delta_diameter,
              state.half_width() / R,
              state.max_penetration / R,
              force > 0. ? state.force / (problem.domain_share() * force) - 1. :
                           0.,
              plastic_work / energy_unit,
              alpha,
              elastic_energy / energy_unit,
              state.energy / problem.domain_share() / energy_unit,
              work / energy_unit,
              support_work / energy_unit,
              error})
          table.add(v);
        table.add(iterations);
        records.emplace_back(step + 1,
                             problem.write_state(directory, step + 1));

        std::ostringstream line;
        line << std::setw(6) << step + 1 << std::scientific
             << std::setprecision(3) << std::setw(11) << path[step]
             << std::setw(12) << delta_com << std::setw(10)
             << state.half_width() / R << std::setw(11) << alpha
             << std::setw(13) << plastic_work / energy_unit << std::setw(12)
             << error << std::setw(6) << iterations << '\n';
        pcout << line.str() << std::flush;
      }

    const auto [residual_com, residual_diameter] = problem.approach();
    CsvTable   summary({"largest_load",
                        "delta_max",
                        "residual_delta_com",
                        "residual_delta_diameter",
                        "plastic_work",
                        "plastic_work_fraction",
                        "plastic_strain_max",
                        "last_elastic_load",
                        "first_plastic_load",
                        "first_yield_load_hertz",
                        "energy_error_max",
                        "steps",
                        "n_dofs"});
    summary.start_row();
    for (const double v : {largest_load,
                           delta_max,
                           residual_com,
                           residual_diameter,
                           plastic_work / energy_unit,
                           plastic_work / largest_work,
                           problem.largest_plastic_strain(),
                           last_elastic_load,
                           first_plastic_load,
                           yield_load,
                           largest_error})
      summary.add(v);
    summary.add(steps);
    summary.add(problem.n_dofs());
    std::ostringstream line;
    line << std::scientific << std::setprecision(6)
         << "Residual indentation: delta_com = " << residual_com
         << " R, delta_diameter = " << residual_diameter
         << " R (largest delta_com " << delta_max
         << " R); plastic work " << plastic_work / energy_unit
         << " P_unit R, " << plastic_work / largest_work
         << " of the work done on the body; largest energy error "
         << largest_error << '\n';
    pcout << line.str() << std::flush;
    on_root(communicator, [&]() {
      table.write(directory + "/indentation.csv");
      summary.write(directory + "/indentation_summary.csv");
      write_atomically(directory + "/contact.pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, records);
      });
    });
  }
} // namespace DiskImpact
