#include "tasks/run_checks.h"

#include "base/run_error.h"
#include "body/solid_geometry.h"
#include "impact/measured_contact_grading.h"
#include "run/parameters.h"

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

    /// Memory per DoF of a three-dimensional run, whose factorization's
    /// fill grows faster than a 2D one's. Measured on task 'modal analysis'
    /// of the whole sphere (one rank, 57 modes): 23 kB per DoF with Q4
    /// (6.8k DoFs), 55 kB with Q5 (13k), 86 kB with Q6 (22k), 40 kB with Q4
    /// on 8 times the cells (52k); on task 'impact' of the quarter sphere
    /// (Q2, MUMPS): 19 kB per DoF at 132k DoFs on one rank, 25 kB at 156k
    /// on two; of a free disk, whose contact line along z fills more:
    /// 34 kB at 63k DoFs (H = R, v = 0.03c, two ranks), 32 kB at 181k
    /// (H = 0.05R, 0.1c, two ranks), 34 kB at 229k (H = 2R, 0.003c, one
    /// rank), 27 kB at 527k and 34 kB at 418k (the same disk with its
    /// section and with its layers refined, one rank).
    constexpr double solid_modal_bytes_per_dof  = 90e3;
    constexpr double solid_impact_bytes_per_dof = 40e3;

    /// The same for a three-dimensional mesh: 3 k^3 DoFs per cell.
    double
    solid_cell_budget(const unsigned int degree,
                      const double       bytes,
                      const unsigned int at_once = 1)
    {
      const double dofs =
        (0.9 * physical_memory() / at_once - fixed_bytes) / bytes;
      return std::max(dofs, 0.) / (3. * degree * degree * degree);
    }

  } // namespace

  void
  in_context(const std::string &context, const std::function<void()> &check)
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

  void
  check_mode_count(const Parameters &parameters, const std::string &entry)
  {
    if (parameters.geometry.dimension() == 3)
      {
        const unsigned int degree = parameters.finite_element.degree;
        Triangulation<3>   mesh;
        create_solid_triangulation(
          parameters.geometry,
          mesh,
          solid_cell_budget(degree, solid_modal_bytes_per_dof));
        DoFHandler<3> dof_handler(mesh);
        dof_handler.distribute_dofs(FESystem<3>(FE_Q<3>(degree), 3));
        const unsigned int wanted =
          parameters.modal_solver.n_elastic_modes() + 6;
        require(2 * wanted <= dof_handler.n_dofs(),
                entry + " needs a finer mesh: " + std::to_string(wanted) +
                  " modes (rigid ones included) of a discretization with " +
                  std::to_string(dof_handler.n_dofs()) +
                  " DoFs; at most half the DoFs can be computed");
        return;
      }
    Triangulation<2> mesh;
    parameters.geometry.create_triangulation(
      mesh, cell_budget(parameters.finite_element.degree, 1));
    const FESystem<2> fe(FE_Q<2>(parameters.finite_element.degree), 2);
    DoFHandler<2>     dof_handler(mesh);
    dof_handler.distribute_dofs(fe);
    const unsigned int wanted =
      parameters.modal_solver.n_elastic_modes() +
      (parameters.geometry.has_symmetry_boundary() ? 1 : 3);
    require(2 * wanted <= dof_handler.n_dofs(),
            entry + " needs a finer mesh: " + std::to_string(wanted) +
              " modes (rigid ones included) of a discretization with " +
              std::to_string(dof_handler.n_dofs()) +
              " DoFs; at most half the DoFs can be computed");
  }

  namespace
  {
    /// Build (on this process alone) the largest mesh @p parameters' task
    /// builds, refused beyond the budget for @p at_once meshes, and check
    /// what depends on the meshes.
    void
    check_meshes(const Parameters &given, const unsigned int at_once)
    {
      // A mesh still to be graded for the measured contact is counted as
      // graded for a wide one.
      const Parameters parameters = with_mesh_graded_for_wide_contact(given);
      if (parameters.geometry.dimension() == 3)
        {
          Triangulation<3> mesh(
            Triangulation<3>::limit_level_difference_at_vertices);
          if (parameters.task().build_largest_solid_mesh)
            parameters.task().build_largest_solid_mesh(
              parameters, mesh, [at_once](const unsigned int degree) {
                return solid_cell_budget(degree,
                                         solid_impact_bytes_per_dof,
                                         at_once);
              });
          return;
        }
      Triangulation<2> mesh(
        Triangulation<2>::limit_level_difference_at_vertices);
      if (parameters.task().build_largest_mesh)
        parameters.task().build_largest_mesh(
          parameters, mesh, [at_once](const unsigned int degree) {
            return cell_budget(degree, at_once);
          });
    }
  } // namespace

  void
  check_before_output(const Parameters &parameters, MPI_Comm communicator)
  {
    const TaskTraits &traits = parameters.task().traits;
    if (!traits.meshes)
      return;
    const unsigned int at_once =
      traits.one_mesh_per_rank ? Utilities::MPI::n_mpi_processes(communicator) :
                                 1;
    on_root(communicator, [&]() { check_meshes(parameters, at_once); });
  }
} // namespace DiskImpact
