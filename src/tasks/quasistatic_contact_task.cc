#include "base/input_error.h"
#include "quasistatic/quasistatic_contact.h"
#include "run/parameters.h"
#include "run/task_registry.h"

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    TaskEntry
    quasistatic_contact_task()
    {
      TaskEntry task;
      task.name        = "quasistatic contact";
      task.description = "the half body pressed on the wall (or its partner) "
                         "by a body force, the contact law delta(P) "
                         "(contact_law.csv); an elastic-plastic body loaded "
                         "and unloaded (indentation.csv).";
      task.traits.partner_body = true;
      task.traits.plasticity   = true;
      task.result_files        = {"contact_law.csv",
                                  "indentation.csv",
                                  "indentation_summary.csv",
                                  "pressure_profile.csv",
                                  "contact.pvd",
                                  "contact_*.vtu",
                                  "contact_*.pvtu"};
      add_own_parameters<QuasistaticContact>(task);
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        parameters.task_parameters<QuasistaticContact>().run(parameters,
                                                             communicator);
      };
      task.check = [](const Parameters &parameters) {
        require(parameters.geometry.has_symmetry_boundary(),
                "Task 'quasistatic contact' needs 'Domain = half disk' (the "
                "symmetry condition holds the rigid motions the wall does "
                "not)");
        parameters.contact.check_wall(parameters.geometry, 0.);
        require(parameters.contact.law_name() == "penalty",
                "Task 'quasistatic contact' needs 'Law = penalty' in "
                "subsection Contact");
        require(!parameters.partner.is_body() ||
                  (!parameters.material.is_plastic() &&
                   !parameters.partner.material().is_plastic()),
                "Task 'quasistatic contact': an elastic-plastic body "
                "('Yield stress' > 0) is pressed on the wall, not on a "
                "partner body, so far");
      };
      task.build_largest_mesh = [](const Parameters &parameters,
                                   Triangulation<2> &mesh,
                                   const auto       &cell_budget) {
        parameters.task_parameters<QuasistaticContact>().create_mesh(
          parameters,
          parameters.task_parameters<QuasistaticContact>().largest_load(),
          mesh,
          cell_budget(parameters.finite_element.degree));
      };
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(quasistatic_contact_task())
} // namespace DiskImpact
