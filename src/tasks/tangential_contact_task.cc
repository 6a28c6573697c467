#include "base/input_error.h"
#include "quasistatic/tangential_contact.h"
#include "run/parameters.h"
#include "run/task_registry.h"

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    TaskEntry
    tangential_contact_task()
    {
      TaskEntry task;
      task.name        = "tangential contact";
      task.description = "the whole disk or the half sphere pressed on the "
                         "wall, then pulled along it against Coulomb friction: "
                         "the tangential compliance against Cattaneo and "
                         "Mindlin (tangential_law.csv).";
      task.traits.three_dimensional = true;
      task.result_files             = {"tangential_law.csv"};
      add_own_parameters<TangentialContact>(task);
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        parameters.task_parameters<TangentialContact>().run(parameters,
                                                            communicator);
      };
      task.check = [](const Parameters &parameters) {
        const auto &geometry = parameters.geometry;
        require(geometry.turns_in_plane() && (geometry.dimension() == 2 ||
                                              geometry.has_symmetry_plane_z()),
                "Task 'tangential contact' needs the whole disk ('Domain = "
                "full disk') or, with 'Dimension = 3', the half sphere "
                "('Domain = half sphere'): the body must move along the wall "
                "and turn");
        parameters.contact.check_wall(geometry, 0.);
        require(parameters.contact.law_name() == "penalty",
                "Task 'tangential contact' needs 'Law = penalty' in "
                "subsection Contact");
        require(parameters.contact.friction_coefficient() > 0.,
                "Task 'tangential contact' needs 'Friction coefficient' > 0 "
                "in subsection Contact");
      };
      build_meshes_for_largest_load<TangentialContact>(task);
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(tangential_contact_task())
} // namespace DiskImpact
