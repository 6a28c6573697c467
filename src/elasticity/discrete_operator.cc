#include "elasticity/discrete_operator.h"

#include <deal.II/base/function_lib.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q_cache.h>

#include <deal.II/lac/la_parallel_vector.h>

#include <deal.II/numerics/vector_tools.h>

namespace DiskImpact
{
  using namespace dealii;

  template <int dim>
  DiscreteOperator<dim>::DiscreteOperator(const unsigned int degree)
      : fe_degree(degree)
  {
  }

  template <int dim>
  unsigned int
  DiscreteOperator<dim>::degree() const
  {
    return fe_degree;
  }

  template <int dim>
  void
  DiscreteOperator<dim>::distribute_dofs(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const FiniteElement<dim>                        &fe)
  {
    mapping = std::make_unique<MappingQ<dim>>(fe_degree);
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    // The components of each support point next to each other: the
    // matrices are then made of dense blocks (used by CondensedSolver and
    // InterleavedMass). The points stay in the order of the cells; the
    // direct solvers choose their own fill-reducing order.
    if (fe.n_components() > 1)
      DoFRenumbering::support_point_wise(dof_handler);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
  }

  template <int dim>
  void
  DiscreteOperator<dim>::conform_mapping_to_constraints(
    const AffineConstraints<double> &hanging)
  {
    if constexpr (dim == 3)
      {
        LinearAlgebra::distributed::Vector<double> positions(
          owned_dofs, relevant_dofs, dof_handler.get_communicator());
        VectorTools::interpolate(*mapping,
                                 dof_handler,
                                 Functions::IdentityFunction<dim>(),
                                 positions);
        positions.update_ghost_values();
        hanging.distribute(positions);
        positions.update_ghost_values();
        auto conforming = std::make_unique<MappingQCache<dim>>(fe_degree);
        conforming->initialize(*mapping, dof_handler, positions, false);
        mapping = std::move(conforming);
      }
  }

  template <int dim>
  void
  DiscreteOperator<dim>::move_constrained_eigenvalues(const double eigenvalue)
  {
    for (const auto i : owned_dofs)
      if (constraints.is_constrained(i))
        mass.set(i, i, stiffness.diag_element(i) / eigenvalue);
    mass.compress(VectorOperation::insert);
  }

  template <int dim>
  const DoFHandler<dim> &
  DiscreteOperator<dim>::get_dof_handler() const
  {
    return dof_handler;
  }

  template <int dim>
  const MappingQ<dim> &
  DiscreteOperator<dim>::get_mapping() const
  {
    return *mapping;
  }

  template <int dim>
  const AffineConstraints<double> &
  DiscreteOperator<dim>::get_constraints() const
  {
    return constraints;
  }

  template <int dim>
  const IndexSet &
  DiscreteOperator<dim>::locally_owned_dofs() const
  {
    return owned_dofs;
  }

  template <int dim>
  const IndexSet &
  DiscreteOperator<dim>::locally_relevant_dofs() const
  {
    return relevant_dofs;
  }

  template <int dim>
  const PETScWrappers::MPI::SparseMatrix &
  DiscreteOperator<dim>::mass_matrix() const
  {
    return mass;
  }

  template <int dim>
  const PETScWrappers::MPI::SparseMatrix &
  DiscreteOperator<dim>::stiffness_matrix() const
  {
    return stiffness;
  }

  template <int dim>
  PETScWrappers::MPI::Vector
  DiscreteOperator<dim>::create_vector() const
  {
    return PETScWrappers::MPI::Vector(owned_dofs,
                                      dof_handler.get_communicator());
  }

  template <int dim>
  PETScWrappers::MPI::Vector
  DiscreteOperator<dim>::create_ghosted(
    const PETScWrappers::MPI::Vector &vector) const
  {
    PETScWrappers::MPI::Vector ghosted(owned_dofs,
                                       relevant_dofs,
                                       dof_handler.get_communicator());
    ghosted = vector;
    return ghosted;
  }

  template class DiscreteOperator<2>;
  template class DiscreteOperator<3>;
} // namespace DiskImpact
