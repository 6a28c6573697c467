#include "tasks/impact.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "output/csv_table.h"
#include "tasks/impact_simulation.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The contact-law constant of the 1-DOF model: "fit" is the measured
    /// C_com = -1 - 2/pi - nu2/4 (docs/contact-law.md), else a number.
    double
    parse_contact_law_constant(const std::string &text, const double nu2)
    {
      if (text == "fit")
        return -1. - 2. / M_PI - nu2 / 4.;
      try
        {
          return std::stod(text);
        }
      catch (const std::exception &)
        {
          throw InputError("Impact: 'Contact law constant' must be 'fit' or "
                           "a number, got '" +
                           text + "'");
        }
    }

  } // namespace

  void
  Impact::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact");
    prm.declare_entry("Velocity",
                      "0.01",
                      Patterns::Double(),
                      "Impact speed v_i in units of c = sqrt(E2 / rho) [-], "
                      "0 < v_i <= 0.5.");
    prm.declare_entry("Elements across contact",
                      "12",
                      Patterns::Integer(4, 1000),
                      "Elements across the largest Hertz half-width expected "
                      "(from the 1-DOF model's largest force); the mesh is "
                      "graded toward the contact point as in task "
                      "'quasistatic contact'.");
    prm.declare_entry("Grading",
                      "0.3",
                      Patterns::Double(0.01, 1),
                      "Growth of the element size with distance from the "
                      "contact zone [-].");
    prm.declare_entry("Contact law constant",
                      "fit",
                      Patterns::Anything(),
                      "Constant C of the log law in the 1-DOF reference model "
                      "(time-step estimate, comparison): 'fit' for the "
                      "measured centre-of-mass law C = -1 - 2/pi - nu2/4, or "
                      "a number.");
    prm.declare_entry("Output interval",
                      "20",
                      Patterns::Integer(0),
                      "Write the deformed state with stresses (impact.pvd) "
                      "every this many steps; 0: only the final state.");
    prm.declare_entry("Mode energies",
                      "20",
                      Patterns::Integer(0, 400),
                      "Task 'impact': project the vibration on this many "
                      "lowest elastic eigenmodes of the same discretization "
                      "(mode_energies.csv: after the impact and averaged over "
                      "the collision, as seed 001's Table 1); 0: none.");
    prm.declare_entry("Velocities",
                      "0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3",
                      Patterns::List(Patterns::Double(), 0),
                      "Task 'sweep': the impact speeds v_i / c [-].");
    prm.declare_entry("Poisson ratios",
                      "",
                      Patterns::List(Patterns::Double(), 0),
                      "Task 'sweep': Poisson ratios (as 'Poisson ratio' of "
                      "subsection Material) [-]; empty: the material's.");
    prm.declare_entry("Relaxation times",
                      "",
                      Patterns::List(Patterns::Double(0.), 0),
                      "Task 'sweep': Kelvin-Voigt relaxation times (as "
                      "'Relaxation time' of subsection Material) [R/c]; "
                      "empty: the material's.");
    prm.declare_entry("Error estimate",
                      "true",
                      Patterns::Bool(),
                      "Task 'sweep': run a convergence study (subsection "
                      "Impact convergence) at each point and report its "
                      "extrapolated epsilon and error bar (epsilon, "
                      "epsilon_error); false: one run per point, no error "
                      "bar.");
    prm.declare_entry("Margin",
                      "0.2",
                      Patterns::Double(0., 10.),
                      "Time simulated after the contact force has returned to "
                      "zero, as a fraction of the contact time [-].");
    prm.leave_subsection();
  }

  void
  Impact::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact");
    impact_velocity         = prm.get_double("Velocity");
    elements_across_contact = prm.get_integer("Elements across contact");
    grading                 = prm.get_double("Grading");
    contact_law_constant    = prm.get("Contact law constant");
    margin                  = prm.get_double("Margin");
    output_interval         = prm.get_integer("Output interval");
    projected_modes         = prm.get_integer("Mode energies");
    sweep_velocities        = get_double_list(prm, "Velocities");
    sweep_poisson_ratios    = get_double_list(prm, "Poisson ratios");
    sweep_relaxation_times  = get_double_list(prm, "Relaxation times");
    error_estimate          = prm.get_bool("Error estimate");
    require_each(
      sweep_velocities,
      [](const double v) { return v > 0. && v <= 0.5; },
      "Impact: every entry of 'Velocities' must satisfy 0 < v/c <= 0.5");
    prm.leave_subsection();
    require(impact_velocity > 0. && impact_velocity <= 0.5,
            "Impact: 'Velocity' must satisfy 0 < v/c <= 0.5, got " +
              Utilities::to_string(impact_velocity));
    if (contact_law_constant != "fit")
      parse_contact_law_constant(contact_law_constant, 0.);
  }

  double
  Impact::velocity() const
  {
    return impact_velocity;
  }

  void
  Impact::set_velocity(const double v)
  {
    impact_velocity = v;
  }

  const std::vector<double> &
  Impact::velocities() const
  {
    return sweep_velocities;
  }

  const std::vector<double> &
  Impact::poisson_ratios() const
  {
    return sweep_poisson_ratios;
  }

  const std::vector<double> &
  Impact::relaxation_times() const
  {
    return sweep_relaxation_times;
  }

  bool
  Impact::estimate_errors() const
  {
    return error_estimate;
  }

  Impact
  Impact::with_mesh_refined(const unsigned int levels) const
  {
    Impact finer                  = *this;
    finer.elements_across_contact = elements_across_contact << levels;
    finer.grading                 = grading / (1u << levels);
    return finer;
  }

  double
  Impact::contact_law_constant_value(const double nu2) const
  {
    return parse_contact_law_constant(contact_law_constant, nu2);
  }

  ImpactSummary
  Impact::run(const Parameters &parameters,
              MPI_Comm          communicator,
              const bool        write_time_series) const
  {
    return ImpactSimulation(parameters, *this, communicator, write_time_series)
      .run();
  }

  void
  Impact::write_summary(const ImpactSummary &s, const std::string &filename)
  {
    summary_table(s).write(filename);
  }

  CsvTable
  Impact::summary_table(const ImpactSummary &s)
  {
    CsvTable table({"velocity",
                    "epsilon",
                    "contact_time",
                    "delta_max",
                    "force_max",
                    "energy_error",
                    "steps",
                    "newton_iterations",
                    "impulse_error",
                    "time_step",
                    "n_dofs",
                    "factorizations",
                    "triangular_solves",
                    "one_dof_contact_time",
                    "one_dof_delta_max",
                    "alpha",
                    "one_dof_epsilon"});
    table.start_row();
    for (const double value : {s.velocity,
                               s.epsilon,
                               s.contact_time,
                               s.delta_max,
                               s.force_max,
                               s.energy_error})
      table.add(value);
    table.add(s.steps);
    table.add(s.newton_iterations);
    table.add(s.impulse_error);
    table.add(s.time_step);
    table.add(s.n_dofs);
    table.add(s.factorizations);
    table.add(s.triangular_solves);
    table.add(s.one_dof_contact_time);
    table.add(s.one_dof_delta_max);
    table.add(s.schwager_alpha);
    table.add(s.one_dof_epsilon);
    return table;
  }
} // namespace DiskImpact
