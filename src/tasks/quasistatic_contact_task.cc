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
      task.description = "the half body (in 3D its quarter) pressed on the "
                         "wall (or its partner) by a body force, the contact "
                         "law delta(P) "
                         "(contact_law.csv); an elastic-plastic body loaded "
                         "and unloaded (indentation.csv).";
      task.traits.partner_body      = true;
      task.traits.plasticity        = true;
      task.traits.three_dimensional = true;
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
        const auto &geometry = parameters.geometry;
        require(geometry.has_symmetry_boundary(),
                "Task 'quasistatic contact' needs 'Domain = half disk' (in "
                "3D the quarter of a disk) or, with 'Dimension = 3', 'Domain "
                "= quarter sphere' (the symmetry conditions hold the rigid "
                "motions the wall does not)");
        require(geometry.dimension() == 2 ||
                  (!parameters.material.is_plastic() &&
                   !parameters.partner.is_body()),
                "Task 'quasistatic contact': in 3D an elastic body is "
                "pressed on the wall, so far (no 'Yield stress', no "
                "'Partner')");
        const auto &own = parameters.task_parameters<QuasistaticContact>();
        require(!own.conforming_mesh() ||
                  (!parameters.partner.is_body() && !geometry.is_sphere()),
                "Quasistatic contact: 'Graded mesh = conforming' takes a "
                "disk on the wall");
        require(geometry.dimension() == 2 || geometry.is_sphere() ||
                  own.conforming_mesh(),
                "Quasistatic contact: a disk in 3D takes 'Graded mesh = "
                "conforming'");
        require(!own.conforming_mesh() || own.elements_across() % 2 == 0,
                "Quasistatic contact: 'Graded mesh = conforming' takes an "
                "even number of 'Elements across contact'");
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
      build_meshes_for_largest_load<QuasistaticContact>(task);
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(quasistatic_contact_task())
} // namespace DiskImpact
