#include "run/impact_convergence_parameters.h"

#include "base/input_error.h"

#include <string>

namespace DiskImpact
{
  using namespace dealii;

  void
  ImpactConvergenceParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact convergence");
    prm.declare_entry("Mesh levels",
                      "3",
                      Patterns::Integer(1, 6),
                      "Runs with every element size and the time step halved "
                      "0, 1, ... times (global refinements + 1, twice the "
                      "elements across the contact, half the grading, half "
                      "the time step) [-]; 1: no mesh study.");
    prm.declare_entry("Time step levels",
                      "1",
                      Patterns::Integer(1, 8),
                      "Runs with the time step alone halved 0, 1, ... times "
                      "[-]: a diagnostic, reported but not added to the error "
                      "bar, which the mesh sequence (with its time step) "
                      "already carries.");
    prm.declare_entry("Penalty levels",
                      "1",
                      Patterns::Integer(1, 6),
                      "Runs with the penalty factor alone multiplied by 4 0, "
                      "1, ... times [-]: a diagnostic, reported but not added "
                      "to the error bar (the penalty k = kappa E2 / h already "
                      "stiffens in the mesh sequence).");
    prm.declare_entry("Target error",
                      "0",
                      Patterns::Double(0.),
                      "Add mesh levels beyond 'Mesh levels', one at a time, "
                      "while epsilon's error bar exceeds this, up to "
                      "'Largest mesh levels' [-]; 0: exactly 'Mesh levels'. "
                      "A sweep adds them per point.");
    prm.declare_entry("Separate time step error",
                      "false",
                      Patterns::Bool(),
                      "Also run the last mesh level's coarser mesh with the "
                      "last level's time step, and where the mesh sequence "
                      "is not clean let the error bar be at least "
                      "3 (|d_t| + |d_h|), the last difference split into "
                      "its time-step part d_t and its mesh part d_h: errors "
                      "of the two that cancel in the last difference then "
                      "cannot make the bar small.");
    prm.declare_entry("Largest mesh levels",
                      "4",
                      Patterns::Integer(1, 6),
                      "With a 'Target error': the most mesh levels a study "
                      "may run [-]; at least 'Mesh levels'.");
    prm.declare_entry("Largest time step halvings",
                      "0",
                      Patterns::Integer(0, 4),
                      "With a 'Target error' and 'Separate time step error': "
                      "the most times the study may halve the time step of "
                      "its last two mesh levels instead of adding a mesh "
                      "level, which it does while the time step's part of "
                      "the last difference is at least half the mesh's. A "
                      "mesh level added after a halving keeps the finest "
                      "step where the finest mesh's own halving moved "
                      "epsilon by less than half the mesh's part, else "
                      "halves it too [-]; 0: never.");
    prm.declare_entry("Halve first above",
                      "0",
                      Patterns::Double(0., 1.),
                      "With 'Largest time step halvings' > 0 and two 'Mesh "
                      "levels': the split run (the base mesh at the second "
                      "level's time step) runs first, and where the time "
                      "step's part it shows, 3 |d_t|, is at least this share "
                      "of the 'Target error', the second mesh level runs at "
                      "the halved time step at once, with its split run: "
                      "its run at the unhalved step would only show that "
                      "the halving is needed [-]; 0: never.");
    prm.declare_entry("Degree levels from",
                      "0",
                      Patterns::Integer(0, 6),
                      "Mesh levels from this one on keep the mesh of the "
                      "level before and raise the element degree by one "
                      "instead; each still halves the time step and doubles "
                      "the penalty factor, as halving the element size "
                      "doubles k = kappa E2 / h [-]; 0: every level halves "
                      "the element size.");
    prm.leave_subsection();
  }

  void
  ImpactConvergenceParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact convergence");
    mesh_levels           = prm.get_integer("Mesh levels");
    time_step_levels      = prm.get_integer("Time step levels");
    penalty_levels        = prm.get_integer("Penalty levels");
    target_error          = prm.get_double("Target error");
    largest_mesh_levels   = prm.get_integer("Largest mesh levels");
    separate_time_step    = prm.get_bool("Separate time step error");
    largest_time_halvings = prm.get_integer("Largest time step halvings");
    degree_levels_from    = prm.get_integer("Degree levels from");
    halve_first_above     = prm.get_double("Halve first above");
    prm.leave_subsection();
    require(halve_first_above == 0. ||
              (largest_time_halvings > 0 && mesh_levels == 2),
            "Impact convergence: 'Halve first above' > 0 needs 'Largest "
            "time step halvings' > 0 and 'Mesh levels = 2'");
    require(degree_levels_from != 1,
            "Impact convergence: 'Degree levels from = 1' would leave the "
            "base mesh unrefined in every level; use 0 (never) or >= 2");
    require(largest_time_halvings == 0 ||
              (target_error > 0. && separate_time_step),
            "Impact convergence: 'Largest time step halvings' > 0 needs a "
            "'Target error' and 'Separate time step error = true'");
    require(target_error == 0. ||
              (mesh_levels >= 2 && largest_mesh_levels >= mesh_levels),
            "Impact convergence: a 'Target error' needs 'Mesh levels' >= 2 "
            "and 'Largest mesh levels' >= 'Mesh levels' (here " +
              std::to_string(mesh_levels) + " and " +
              std::to_string(largest_mesh_levels) + ")");
  }
} // namespace DiskImpact
