#include "quasistatic/quasistatic_contact.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "base/run_error.h"
#include "body/solid_geometry.h"
#include "contact/penalty_law.h"
#include "impact/impact_estimates.h"
#include "impact/impact_mesh.h"
#include "output/atomic_file.h"
#include "output/csv_table.h"
#include "quasistatic/quasistatic_indentation.h"
#include "quasistatic/quasistatic_pair.h"
#include "quasistatic/wall_contact_problem.h"
#include "reference/sphere_finite_size.h"
#include "reference/two_body_contact.h"
#include "reference/wall_contact_theory.h"
#include "run/parameters.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The penalty factor kappa of the task's law ('Law = penalty').
    double
    penalty_factor(const Parameters &parameters)
    {
      return dynamic_cast<const PenaltyLaw &>(parameters.contact.parsed())
        .penalty_factor();
    }

  } // namespace

  void
  QuasistaticContact::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Quasistatic contact");
    prm.declare_entry("Loads",
                      "1e-5, 1e-4, 1e-3",
                      Patterns::List(Patterns::Double(), 1),
                      "Loads [-], each > 0 and <= 0.05: P / (pi E2 R) for a "
                      "disk, P the total body force on the (full) disk per "
                      "unit thickness; P / (pi E* R^2) for a sphere, P the "
                      "total force (E* = E / (1 - nu^2)).");
    prm.declare_entry("Elements across contact",
                      "16",
                      Patterns::Integer(4, 1000),
                      "Number of elements across the Hertz half-width "
                      "a = 2 R sqrt(P / (pi E2 R)) (disk) or contact radius "
                      "a = (3 P R / (4 E*))^(1/3) (sphere): cells closer "
                      "than 1.5 a to the contact point get size <= a / this "
                      "number ('Graded mesh = conforming': an even number; a "
                      "disk in 3D's layers are as thin at its faces).");
    prm.declare_entry("Graded mesh",
                      "hanging nodes",
                      Patterns::Selection("hanging nodes|conforming"),
                      "'hanging nodes': the mesh refined toward the contact "
                      "point; 'conforming': graded with half the elements "
                      "across and twice the grading, then halved without "
                      "hanging nodes (the impact's 'Graded mesh = "
                      "conforming'). A disk in 3D takes 'conforming': its "
                      "section is that mesh, extruded through layers graded "
                      "toward its face, and a plane model on 'conforming' "
                      "computes on its section.");
    prm.declare_entry("Grading",
                      "0.3",
                      Patterns::Double(0.01, 1),
                      "Growth of the element size with distance beyond 1.5 a "
                      "from the contact point (a disk in 3D: also of the "
                      "layers' thickness away from its faces) [-].");
    prm.declare_entry("Newton tolerance",
                      "1e-10",
                      Patterns::Double(1e-15, 1e-3),
                      "Newton stops when |residual| <= this times |body "
                      "force vector| [-].");
    prm.declare_entry("Maximum Newton iterations",
                      "30",
                      Patterns::Integer(1, 1000),
                      "Newton iterations allowed per load before the run "
                      "stops with an error.");
    prm.declare_entry("Indentation steps",
                      "20",
                      Patterns::Integer(1, 10000),
                      "An elastic-plastic body ('Yield stress' > 0) is "
                      "loaded to the largest of 'Loads' in this many equal "
                      "steps, unloaded in as many and left at load 0 "
                      "(indentation.csv); the other loads are not used.");
    prm.leave_subsection();
  }

  void
  QuasistaticContact::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Quasistatic contact");
    loads                   = get_double_list(prm, "Loads");
    elements_across_contact = prm.get_integer("Elements across contact");
    conforming              = prm.get("Graded mesh") == "conforming";
    grading                 = prm.get_double("Grading");
    newton_tolerance        = prm.get_double("Newton tolerance");
    max_newton_iterations   = prm.get_integer("Maximum Newton iterations");
    indentation_steps       = prm.get_integer("Indentation steps");
    prm.leave_subsection();
    for (const double load : loads)
      require(load > 0. && load <= 0.05,
              "Quasistatic contact: every entry of 'Loads' must satisfy "
              "0 < P/(pi E2 R) <= 0.05, got " +
                Utilities::to_string(load));
  }

  double
  QuasistaticContact::largest_load() const
  {
    return *std::max_element(loads.begin(), loads.end());
  }

  template <int dim>
  void
  QuasistaticContact::create_mesh(const Parameters   &parameters,
                                  const double        load,
                                  Triangulation<dim> &triangulation,
                                  const double        max_cells) const
  {
    const auto &geometry = parameters.geometry;
    const bool  sphere   = geometry.is_sphere();
    const auto  theory   = Reference::wall_contact_theory(sphere);
    double      a        = theory->half_width(load) * geometry.radius();
    if (conforming)
      {
        // The impact's conforming mesh, graded for this load.
        Parameters graded = parameters;
        graded.impact     = parameters.impact.with_mesh_graded_for(
          a / geometry.radius(), elements_across_contact, grading, true);
        create_impact_mesh(graded, triangulation, max_cells);
        return;
      }
    if constexpr (dim == 3)
      create_solid_triangulation(geometry, triangulation, max_cells);
    else if (parameters.partner.is_body())
      {
        // Both bodies, graded for the pair's Hertz half-width.
        parameters.partner.create_pair_triangulation(geometry,
                                                     triangulation,
                                                     max_cells);
        const auto [body, partner] = contact_bodies(parameters);
        a =
          Reference::two_body_half_width(sphere,
                                         load * theory->force_unit(body.modulus,
                                                                   body.radius),
                                         body,
                                         partner);
      }
    else
      geometry.create_triangulation(triangulation, max_cells);
    refine_toward_contact(triangulation,
                          embedded<dim>(geometry.contact_point()),
                          a,
                          elements_across_contact,
                          grading,
                          default_fine_zone_radius,
                          max_cells);
  }

  template void
  QuasistaticContact::create_mesh(const Parameters &,
                                  double,
                                  Triangulation<2> &,
                                  double) const;
  template void
  QuasistaticContact::create_mesh(const Parameters &,
                                  double,
                                  Triangulation<3> &,
                                  double) const;

  void
  QuasistaticContact::run(const Parameters &parameters,
                          MPI_Comm          communicator) const
  {
    if (parameters.partner.is_body())
      return run_pair(parameters, communicator);
    if (parameters.material.is_plastic())
      return QuasistaticIndentation{largest_load(),
                                    indentation_steps,
                                    newton_tolerance,
                                    max_newton_iterations}
        .run(parameters, communicator);
    if (parameters.geometry.dimension() == 3)
      run_elastic<3>(parameters, communicator);
    else
      run_elastic<2>(parameters, communicator);
  }

  template <int dim>
  void
  QuasistaticContact::run_elastic(const Parameters &parameters,
                                  MPI_Comm          communicator) const
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(communicator) ==
                               0);
    const std::string &directory = parameters.run.output_directory;
    const auto        &geometry  = parameters.geometry;
    const double       R         = geometry.radius();
    const double       nu2       = parameters.material.in_plane_poisson_ratio();
    const auto theory = Reference::wall_contact_theory(geometry.is_sphere());
    const std::string           symbol      = theory->constant_symbol();
    const Reference::FirstYield hertz_yield = hertz_first_yield(parameters);

    // In 3D neither the first yield nor the pressure profile (which
    // varies across a disk's thickness): the deformed states show them.
    std::vector<std::string> columns = {"load",
                                        "delta_com",
                                        "delta_diameter",
                                        "half_width",
                                        "penetration",
                                        symbol + "_com",
                                        symbol + "_diameter",
                                        "newton_iterations",
                                        "hertz_half_width",
                                        "force_balance_error",
                                        "penalty_factor",
                                        "h_contact",
                                        "n_dofs",
                                        "poisson_ratio_2d"};
    if constexpr (dim == 2)
      columns.insert(columns.end(),
                     {"first_yield_pressure_ratio",
                      "first_yield_depth",
                      "first_yield_offset",
                      "first_yield_pressure_ratio_hertz",
                      "first_yield_depth_hertz"});
    else if (!geometry.is_sphere())
      columns.insert(columns.end(), {"thickness", "faces_held"});
    CsvTable law(columns);
    CsvTable profile({"load", "y", "pressure", "pressure_hertz"});
    std::vector<std::pair<double, std::string>> records;

    pcout << "     load        " << symbol << "_com    " << symbol
          << "_diameter   a/a_Hertz-1   force bal.   penetration  Newton   "
             "DoFs"
          << (dim == 2 ? "   p0/Y first yield\n" : "\n");
    for (unsigned int i = 0; i < loads.size(); ++i)
      {
        WallContactProblem<dim> problem(parameters,
                                        loads[i],
                                        loads[i],
                                        communicator);
        // Start from the rigid translation whose overlap with the wall is
        // as wide as the Hertz contact: depth a^2 / (2 R).
        const double a_hertz = theory->half_width(loads[i]);
        problem.translate(0.5 * a_hertz * a_hertz);
        problem.solve(newton_tolerance, max_newton_iterations);
        const ContactLawPoint p   = problem.results();
        const double constant_com = theory->constant_from(p.load, p.delta_com);
        const double constant_diameter =
          theory->constant_from(p.load, p.delta_diameter);
        law.start_row();
        for (const double v : {p.load,
                               p.delta_com,
                               p.delta_diameter,
                               p.half_width,
                               p.penetration,
                               constant_com,
                               constant_diameter})
          law.add(v);
        law.add(p.newton_iterations);
        for (const double v : {a_hertz,
                               p.force_balance,
                               penalty_factor(parameters),
                               p.h_contact})
          law.add(v);
        law.add(p.n_dofs);
        law.add(nu2);
        if constexpr (dim == 2)
          {
            // p0 / Y at first yield: the FE's, and Hertz's half-space.
            for (const double v : {1. / p.von_mises_max,
                                   p.von_mises_depth,
                                   p.von_mises_offset,
                                   hertz_yield.pressure_ratio,
                                   hertz_yield.depth})
              law.add(v);

            // Pressure in units of P / R (disk) or P / R^2 (sphere) against
            // Hertz (Gerl & Zippelius 1999, eq. 46).
            for (const auto &[y, pressure] : problem.pressure_profile())
              {
                const double t = y / R;
                profile.start_row();
                profile.add(p.load);
                profile.add(t);
                profile.add(pressure / problem.pressure_unit());
                profile.add(theory->pressure(t, p.load));
              }
          }
        else if (!geometry.is_sphere())
          {
            law.add(geometry.thickness() / R);
            law.add(geometry.faces_held() ? 1u : 0u);
          }
        records.emplace_back(p.load, problem.write_state(directory, i));

        std::ostringstream line;
        line << std::scientific << std::setprecision(3) << std::setw(10)
             << p.load << std::fixed << std::setprecision(6) << std::setw(12)
             << constant_com << std::setw(12) << constant_diameter
             << std::scientific << std::setprecision(2) << std::setw(14)
             << p.half_width / a_hertz - 1. << std::setw(13) << p.force_balance
             << std::setw(13) << p.penetration << std::setw(7)
             << p.newton_iterations << std::setw(9) << p.n_dofs;
        if (dim == 2)
          line << std::fixed << std::setprecision(4) << std::setw(10)
               << 1. / p.von_mises_max << " at " << std::setprecision(3)
               << p.von_mises_depth << " a";
        pcout << line.str() << std::endl;
      }
    if (dim == 2)
      pcout << "First yield (von Mises) in Hertz's half-space: p0/Y = "
            << hertz_yield.pressure_ratio << " at depth " << hertz_yield.depth
            << " a" << std::endl;
    if (geometry.is_sphere())
      {
        const auto derived = Reference::sphere_finite_size_constants(
          parameters.material.poisson_ratio());
        std::ostringstream line;
        line << std::fixed << std::setprecision(6)
             << "Sphere: D = (delta - delta_Hertz) E* R / P, delta_Hertz = "
                "(9 P^2 / (16 R E*^2))^(1/3)\n"
             << "Derived (docs/theory/sphere-finite-size.md): D = D0 + D1 "
                "ln(a/R), D1 = "
             << derived.log_coefficient << ", D0 = " << derived.centre_of_mass
             << " (com), " << derived.diameter << " (diameter)\n";
        pcout << line.str() << std::flush;
      }
    else if (dim == 2 || geometry.faces_held())
      pcout << "Gerl & Zippelius 1999, eq. 57: C = -1 - nu2 = " << -1. - nu2
            << std::endl;
    on_root(communicator, [&]() {
      law.write(directory + "/contact_law.csv");
      if (dim == 2)
        profile.write(directory + "/pressure_profile.csv");
      write_atomically(directory + "/contact.pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, records);
      });
    });
  }

  void
  QuasistaticContact::run_pair(const Parameters &parameters,
                               MPI_Comm          communicator) const
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(communicator) ==
                               0);
    const std::string &directory = parameters.run.output_directory;
    const bool         sphere    = parameters.geometry.is_axisymmetric();
    const double       R         = parameters.geometry.radius();
    const auto         theory    = Reference::wall_contact_theory(sphere);
    const std::string  C         = theory->constant_symbol();

    CsvTable                                    law({"load",
                                                     "pair_load",
                                                     "approach",
                                                     "share_body",
                                                     "share_partner",
                                                     "half_width",
                                                     "hertz_half_width",
                                                     "penetration",
                                                     C + "_pair",
                                                     C + "_eff",
                                                     C + "_body",
                                                     C + "_body_wall",
                                                     C + "_partner",
                                                     C + "_partner_wall",
                                                     "newton_iterations",
                                                     "force_balance_error",
                                                     "penalty_factor",
                                                     "h_contact",
                                                     "n_dofs",
                                                     "radius_ratio",
                                                     "modulus_ratio",
                                                     "poisson_ratio_2d",
                                                     "partner_poisson_ratio_2d"});
    std::vector<std::pair<double, std::string>> records;

    pcout << "Two bodies pressed together: the constants of the approach of "
             "the centres (pair, against the derived "
          << C << "_eff) and of each body's share\n"
          << "     load      " << C << "_pair      " << C << "_eff     " << C
          << "_body   " << C
          << "_partner  a/a_Hertz-1  force bal.  "
             "penetration Newton     DoFs\n";
    for (unsigned int i = 0; i < loads.size(); ++i)
      {
        QuasistaticPair problem(parameters, loads[i], communicator);
        problem.solve(newton_tolerance, max_newton_iterations);
        const PairContactPoint p    = problem.results();
        const auto &[body, partner] = problem.bodies();
        const auto equivalent =
          Reference::equivalent_body(sphere, body, partner);
        const double P             = problem.force();
        const double a             = problem.hertz_half_width();
        const double constant_pair = Reference::wall_law_constant(
          sphere, P, p.approach * R, a, equivalent);
        const double constant_body =
          Reference::wall_law_constant(sphere, P, p.shares[0] * R, a, body);
        const double constant_partner =
          Reference::wall_law_constant(sphere, P, p.shares[1] * R, a, partner);
        law.start_row();
        for (const double v :
             {p.load,
              P / theory->force_unit(equivalent.modulus, equivalent.radius),
              p.approach,
              p.shares[0],
              p.shares[1],
              p.half_width,
              a / R,
              p.penetration,
              constant_pair,
              equivalent.constant,
              constant_body,
              body.constant,
              constant_partner,
              partner.constant})
          law.add(v);
        law.add(p.newton_iterations);
        for (const double v :
             {p.force_balance, penalty_factor(parameters), p.h_contact})
          law.add(v);
        law.add(p.n_dofs);
        for (const double v :
             {partner.radius / body.radius,
              partner.modulus / body.modulus,
              parameters.material.in_plane_poisson_ratio(),
              parameters.partner.material().in_plane_poisson_ratio()})
          law.add(v);
        records.emplace_back(p.load, problem.write_state(directory, i));

        std::ostringstream line;
        line << std::scientific << std::setprecision(3) << std::setw(10)
             << p.load << std::fixed << std::setprecision(6) << std::setw(12)
             << constant_pair << std::setw(12) << equivalent.constant
             << std::setw(12) << constant_body << std::setw(12)
             << constant_partner << std::scientific << std::setprecision(2)
             << std::setw(13) << p.half_width * R / a - 1. << std::setw(12)
             << p.force_balance << std::setw(12) << p.penetration
             << std::setw(7) << p.newton_iterations << std::setw(9) << p.n_dofs
             << '\n';
        pcout << line.str() << std::flush;
      }
    on_root(communicator, [&]() {
      law.write(directory + "/contact_law.csv");
      write_atomically(directory + "/contact.pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, records);
      });
    });
  }
} // namespace DiskImpact
