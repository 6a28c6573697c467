#include "tasks/run_checks.h"

#include "base/parameters.h"
#include "base/run_error.h"

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <unistd.h>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// Memory of a run: a fixed part (libraries, the modal projection) and
    /// a part per degree of freedom (matrices, the factorization, vectors),
    /// measured on task 'impact' (200 MB and 3.5 kB per DoF from 7k to 50k
    /// DoFs, Q2), with a margin for the factorization's growth.
    constexpr double fixed_bytes   = 250e6;
    constexpr double bytes_per_dof = 6e3;

    /// The physical memory of this machine [bytes].
    double
    physical_memory()
    {
      return static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
             static_cast<double>(sysconf(_SC_PAGE_SIZE));
    }

    /**
     * The cells a mesh of Q_@p degree elements may have when @p at_once
     * such meshes are in memory together: 2 k^2 DoFs per cell (two
     * components, k^2 nodes per cell of a large mesh).
     */
    double
    cell_budget(const unsigned int degree, const unsigned int at_once)
    {
      const double dofs =
        (0.9 * physical_memory() / at_once - fixed_bytes) / bytes_per_dof;
      return std::max(dofs, 0.) / (2. * degree * degree);
    }

    /// The mesh of @p parameters' geometry within the cell budget.
    void
    create_mesh(const Parameters  &parameters,
                Triangulation<2>  &mesh,
                const unsigned int at_once)
    {
      parameters.geometry.create_triangulation(
        mesh, cell_budget(parameters.finite_element.degree, at_once));
    }

    /// Rethrow an InputError of @p check with @p context in front.
    template <typename Check>
    void
    in_context(const std::string &context, Check &&check)
    {
      try
        {
          check();
        }
      catch (const InputError &e)
        {
          throw InputError(context + ": " + e.what());
        }
    }

    /// The modes a modal analysis asks for must be well below the DoFs.
    void
    check_mode_count(const Parameters &parameters, const std::string &entry)
    {
      Triangulation<2> mesh;
      create_mesh(parameters, mesh, 1);
      const FESystem<2> fe(FE_Q<2>(parameters.finite_element.degree), 2);
      DoFHandler<2>     dof_handler(mesh);
      dof_handler.distribute_dofs(fe);
      const unsigned int wanted = parameters.modal_solver.n_elastic_modes() +
                                  (parameters.geometry.is_half_disk() ? 1 : 3);
      require(2 * wanted <= dof_handler.n_dofs(),
              entry + " needs a finer mesh: " + std::to_string(wanted) +
                " modes (rigid ones included) of a discretization with " +
                std::to_string(dof_handler.n_dofs()) +
                " DoFs; at most half the DoFs can be computed");
    }

    /// Build (on this process alone) the largest mesh @p parameters' task
    /// builds, refused beyond the budget for @p at_once meshes, and check
    /// what depends on the meshes.
    void
    check_meshes(const Parameters &parameters, const unsigned int at_once)
    {
      const unsigned int degree = parameters.finite_element.degree;
      const double       budget = cell_budget(degree, at_once);
      Triangulation<2>   mesh(
        Triangulation<2>::limit_level_difference_at_vertices);
      switch (parameters.run.task)
        {
          case Task::modal_analysis:
            check_mode_count(parameters, "Modal analysis: 'Number of modes'");
            break;
          case Task::modal_convergence:
            in_context("Modal convergence: the finest of 'Refinement levels' "
                       "and 'Degrees'",
                       [&]() {
                         create_mesh(parameters.modal_convergence.finest(
                                       parameters),
                                     mesh,
                                     at_once);
                       });
            check_mode_count(parameters.modal_convergence.coarsest(parameters),
                             "Modal convergence: 'Modes compared' on the "
                             "coarsest of 'Refinement levels' and 'Degrees'");
            break;
          case Task::quasistatic_contact:
            parameters.quasistatic_contact.create_mesh(
              parameters,
              parameters.quasistatic_contact.largest_load(),
              mesh,
              budget);
            break;
          case Task::impact:
            parameters.impact.create_mesh(parameters, mesh, budget);
            break;
          case Task::impact_convergence:
            in_context("Impact convergence: the finest of 'Mesh levels'",
                       [&]() {
                         // a degree level's budget is its own degree's
                         const Parameters finest =
                           parameters.impact_convergence.finest(parameters);
                         finest.impact.create_mesh(
                           finest,
                           mesh,
                           cell_budget(finest.finite_element.degree, at_once));
                       });
            break;
          case Task::sweep:
          case Task::restitution_law:
            in_context("Sweep: the fastest impact's finest mesh", [&]() {
              // The fastest impact needs the largest contact zone.
              Parameters fastest =
                parameters.impact.estimate_errors() ?
                  parameters.impact_convergence.finest(parameters) :
                  parameters;
              const auto &velocities = parameters.impact.velocities();
              fastest.impact.set_velocity(
                *std::max_element(velocities.begin(), velocities.end()));
              fastest.impact.create_mesh(
                fastest,
                mesh,
                cell_budget(fastest.finite_element.degree, at_once));
            });
            break;
          case Task::reference_models:
          case Task::modal_expansion_impact:
            break;
        }
    }

    /// Whether the task builds finite-element meshes.
    bool
    uses_mesh(const Task task)
    {
      return task != Task::reference_models &&
             task != Task::modal_expansion_impact;
    }

    /// Whether each rank runs whole impacts of its own at once.
    bool
    runs_one_mesh_per_rank(const Task task)
    {
      return task == Task::sweep || task == Task::restitution_law ||
             task == Task::impact_convergence;
    }
  } // namespace

  void
  check_before_output(const Parameters &parameters, MPI_Comm communicator)
  {
    const Task task = parameters.run.task;
    if (!uses_mesh(task))
      return;
    const unsigned int at_once =
      runs_one_mesh_per_rank(task) ?
        Utilities::MPI::n_mpi_processes(communicator) :
        1;
    on_root(communicator, [&]() { check_meshes(parameters, at_once); });
  }
} // namespace DiskImpact
