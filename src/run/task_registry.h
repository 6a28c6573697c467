#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <mpi.h>

#include <any>
#include <functional>
#include <string>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /// What the checks of a run need to know of its task.
  struct TaskTraits
  {
    /// Runs impacts against the wall or a partner: the wall must touch the
    /// body, and 'Units = SI' applies.
    bool impacts = false;
    /// Runs the sweep over 'Velocities' (a resumable restitution.csv).
    bool sweeps = false;
    /// Computes the free body's modes: an empty 'Domain' is the whole body.
    bool modal = false;
    /// Builds finite-element meshes (checked before anything is written).
    bool meshes = true;
    /// Each rank runs whole impacts of its own at once.
    bool one_mesh_per_rank = false;
    /// Computes a deformable partner ('Kind = body' in subsection Partner).
    bool partner_body = false;
    /// Computes a sphere ('Body = sphere').
    bool sphere = true;
    /// Computes three-dimensional bodies ('Dimension = 3').
    bool three_dimensional = false;
    /// Computes elastic-plastic bodies ('Yield stress' > 0).
    bool plasticity = false;
  };

  /**
   * A task: what a value of 'Task' runs. Each task is one file pair that
   * registers itself with
   *
   *   DISKIMPACT_REGISTER_TASK(make_entry())
   *
   * giving its name, description, traits, result files and functions;
   * nothing else names it. A task's own subsection is declared and parsed
   * by its entry; the subsections several tasks share belong to
   * Parameters.
   */
  struct TaskEntry
  {
    std::string name;
    /// One sentence for the 'Task' entry's documentation.
    std::string description;
    TaskTraits  traits;
    /// The files the task writes (shell wildcards): what an earlier run may
    /// have left in the output directory.
    std::vector<std::string> result_files;
    /// Run it; @p resume: keep the finished points of an earlier sweep.
    std::function<
      void(const Parameters &parameters, bool resume, MPI_Comm communicator)>
      run;
    /// Checks across subsections after parsing (InputError on failure);
    /// optional.
    std::function<void(const Parameters &parameters)> check;
    /// Build the largest mesh the task builds on @p mesh, refused (an
    /// InputError) beyond @p cell_budget(degree) cells; optional.
    std::function<void(const Parameters                          &parameters,
                       dealii::Triangulation<2>                  &mesh,
                       const std::function<double(unsigned int)> &cell_budget)>
      build_largest_mesh;
    /// The same for a three-dimensional body ('Dimension = 3'); optional.
    std::function<void(const Parameters                          &parameters,
                       dealii::Triangulation<3>                  &mesh,
                       const std::function<double(unsigned int)> &cell_budget)>
      build_largest_solid_mesh;
    /// The files of an earlier run in the output directory to keep, besides
    /// a resumed sweep's table; optional.
    std::function<std::vector<std::string>(const Parameters &parameters)>
      kept_results;
    /// Its own subsection: declared with the others, parsed (and checked)
    /// in every run, kept in Parameters for the run of this task, which
    /// reads it back with Parameters::task_parameters<T>(); optional.
    std::function<void(dealii::ParameterHandler &prm)>     declare_parameters;
    std::function<std::any(dealii::ParameterHandler &prm)> parse_parameters;
  };

  /**
   * Give @p task the subsection of the parameter class @p Own (a static
   * declare_parameters(prm) and a member parse_parameters(prm)), which the
   * task reads back with Parameters::task_parameters<Own>().
   */
  template <typename Own>
  void
  add_own_parameters(TaskEntry &task)
  {
    task.declare_parameters = Own::declare_parameters;
    task.parse_parameters   = [](dealii::ParameterHandler &prm) {
      Own own;
      own.parse_parameters(prm);
      return std::any(own);
    };
  }

  /**
   * Give @p task its largest meshes in two and three dimensions: those its
   * own parameters (add_own_parameters<Own>()) build with
   * Own::create_mesh(parameters, load, mesh, max_cells) for
   * Own::largest_load(). Call where Parameters is complete.
   */
  template <typename Own>
  void
  build_meshes_for_largest_load(TaskEntry &task)
  {
    const auto build =
      [](const auto &parameters, auto &mesh, const auto &cell_budget) {
        const auto &own = parameters.template task_parameters<Own>();
        own.create_mesh(parameters,
                        own.largest_load(),
                        mesh,
                        cell_budget(parameters.finite_element.degree));
      };
    task.build_largest_mesh       = build;
    task.build_largest_solid_mesh = build;
  }

  /// The registry of tasks, by name.
  namespace Tasks
  {
    /// Add a task (DISKIMPACT_REGISTER_TASK does it).
    bool
    add(const TaskEntry &entry);
    /// The tasks registered, sorted by name.
    std::vector<TaskEntry>
    all();
    /// The task named @p name; an InputError if there is none.
    const TaskEntry &
    get(const std::string &name);
    /// Declare 'Task' (the names registered).
    void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Declare each task's own subsection.
    void
    declare_own_parameters(dealii::ParameterHandler &prm);
  } // namespace Tasks
} // namespace DiskImpact

/// Register the TaskEntry @p entry.
#define DISKIMPACT_REGISTER_TASK(entry)                           \
  namespace                                                       \
  {                                                               \
    const bool task_registered = ::DiskImpact::Tasks::add(entry); \
  }
