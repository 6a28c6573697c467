#include "base/input_error.h"
#include "base/run_error.h"
#include "impact/impact_estimates.h"
#include "impact/impact_mesh.h"
#include "impact/impact_simulation.h"
#include "impact/measured_contact_grading.h"
#include "run/parameters.h"
#include "run/task_registry.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The oblique impact's results of @p s.
    void
    print_oblique(const ImpactSummary &s, std::ostream &out)
    {
      const ObliqueSummary &o = s.oblique;
      out << "  tangential: v_t = " << o.v_tangential_initial << " -> "
          << o.v_tangential_final
          << " c (restitution " << o.tangential_restitution()
          << "), spin = " << o.spin_initial << " -> " << o.spin_final
          << " c/R\n"
          << "  contact point: v_t - omega R = " << o.v_contact_initial
          << " -> " << o.v_contact_final << " c (restitution "
          << o.contact_point_restitution() << "), rebound angle "
          << o.rebound_angle << " degrees";
      if (std::isfinite(o.psi_incident))
        out << ", psi " << o.psi_incident << " -> " << o.psi_rebound;
      out << "\n  friction work = " << o.friction_work
          << " of E(0), tangential impulse error = "
          << o.tangential_impulse_error
          << ", angular impulse error = " << o.angular_impulse_error << "\n";
    }

    /// Task 'impact': one impact, its time series, summary and a printout.
    void
    run_impact_task(const Parameters &given, MPI_Comm communicator)
    {
      ConditionalOStream pcout(std::cout,
                               Utilities::MPI::this_mpi_process(communicator) ==
                                 0);
      pcout << "Impact at v = " << given.impact.velocity() << " c";
      if (given.impact.is_oblique())
        pcout << ", angle of incidence "
              << given.impact.incidence_angle_degrees() << " degrees, spin "
              << given.impact.spin() << " c/R";
      if (given.contact.friction_coefficient() > 0.)
        pcout << ", friction coefficient "
              << given.contact.friction_coefficient();
      pcout << std::endl;
      // The header first: the measuring impact runs without output.
      const Parameters parameters =
        with_mesh_graded_for_measured_contact(given, communicator);
      if (given.impact.grades_for_measured_contact())
        pcout << describe_measured_grading(parameters) << std::endl;
      const ImpactSummary s = run_impact(parameters, communicator);
      on_root(communicator, [&]() {
        write_summary(s, parameters.run.output_directory + "/summary.csv");
      });
      const bool         sphere = parameters.geometry.is_sphere();
      const std::string  model  = sphere ? "1-DOF Hertz" : "1-DOF log law";
      std::ostringstream out;
      out.precision(8);
      out << "  DoFs " << s.n_dofs << ", time step " << s.time_step
          << " R/c, steps " << s.steps << ", Newton iterations "
          << s.newton_iterations << ", factorizations " << s.factorizations
          << ", triangular solves " << s.triangular_solves << "\n"
          << "  epsilon = " << s.epsilon << " (" << model << ": "
          << s.one_dof_epsilon
          << "; ended at zero overlap: " << s.one_dof_epsilon_overlap
          << "; unloading law: " << s.one_dof_epsilon_unloading << ")\n"
          << "  contact time = " << s.contact_time << " R/c (" << model << ": "
          << s.one_dof_contact_time << ")\n"
          << "  delta_max = " << s.delta_max << " R (" << model << ": "
          << s.one_dof_delta_max << ")\n"
          << "  force_max = " << s.force_max << (sphere ? " E* R^2" : " E2 R")
          << "\n";
      if (parameters.geometry.dimension() == 2 &&
          std::isfinite(s.von_mises_max))
        out << "  largest von Mises stress = " << s.von_mises_max
            << (sphere ? " E*" : " E2") << " at depth " << s.von_mises_depth
            << " R below the contact point (first yield where it reaches "
               "Y)\n";
      out << (sphere ? "  Ramírez et al.'s u = (v / g*)^(1/5) = " :
                       "  Schwager's alpha = tau sqrt(pi E2 / m) = ")
          << (sphere ? s.ramirez_u : s.schwager_alpha) << "\n"
          << "  energy error = " << s.energy_error
          << ", impulse error = " << s.impulse_error << "\n"
          << "  time stepping: " << s.wall_time_loop << " s, "
          << s.wall_time_loop / s.steps * 1e3 << " ms per step = "
          << s.wall_time_loop / s.steps / s.triangular_solve_time
          << " solves with the factorized matrix (one: "
          << s.triangular_solve_time * 1e3 << " ms); " << s.contact_dofs
          << " contact DoFs condensed\n"
          << "  peak memory " << s.peak_memory_mb << " MB (all ranks)\n";
      if (std::isfinite(s.plastic_work))
        out << "  plastic work = " << s.plastic_work
            << " of E(0), largest equivalent plastic strain = "
            << s.plastic_strain_max << ", plastic iterations "
            << s.plastic_iterations << " (" << s.tangent_factorizations
            << " with a new tangent)\n";
      out << "  energy left in vibration: " << s.vibration_fraction
          << " of E(0)";
      if (parameters.partner.is_body())
        out << " (body), " << s.partner_vibration_fraction
            << " (partner); momentum error " << s.momentum_error
            << "\n  two bodies: v is the relative speed, epsilon = -(v1' - "
               "v2') / (v1 - v2), delta_max the approach of the centres of "
               "mass";
      out << "\n";
      if (std::isfinite(s.oblique.v_tangential_initial))
        print_oblique(s, out);
      const UnitSystem &units = parameters.units;
      if (units.is_si())
        out
          << "  in SI: v = " << parameters.impact.velocity() * units.speed()
          << " m/s, epsilon = " << s.epsilon
          << ", contact time = " << s.contact_time * units.time()
          << " s, delta_max = " << s.delta_max * units.length()
          << " m, force_max = " << s.force_max * units.force() << ' '
          << units.force_name()
          << (parameters.geometry.dimension() == 2 &&
                  std::isfinite(s.von_mises_max) ?
                ", largest von Mises stress = " +
                  approximately(s.von_mises_max * units.young_modulus() *
                                  parameters.material.in_plane_young_modulus() /
                                  parameters.material.young_modulus(),
                                8) +
                  " Pa" :
                std::string())
          << "\n";
      pcout << out.str();
    }
  } // namespace

  namespace
  {
    TaskEntry
    impact_task()
    {
      TaskEntry task;
      task.name        = "impact";
      task.description = "the body hits the wall (or its partner) with speed "
                         "v (impact.csv, summary.csv).";
      task.traits.impacts           = true;
      task.traits.partner_body      = true;
      task.traits.three_dimensional = true;
      task.traits.plasticity        = true;
      task.result_files             = {"summary.csv",
                                       "impact.csv",
                                       "mode_energies.csv",
                                       "impact.h5",
                                       "impact.pvd",
                                       "impact_*.vtu",
                                       "impact_*.pvtu"};
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        run_impact_task(parameters, communicator);
      };
      task.check = [](const Parameters &parameters) {
        check_impact_time_step(parameters);
      };
      const auto build =
        [](const Parameters &parameters, auto &mesh, const auto &cell_budget) {
          create_impact_mesh(parameters,
                             mesh,
                             cell_budget(parameters.finite_element.degree));
        };
      task.build_largest_mesh       = build;
      task.build_largest_solid_mesh = build;
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(impact_task())
} // namespace DiskImpact
