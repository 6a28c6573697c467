#include "elasticity/discrete_operator.h"

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

namespace DiskImpact
{
  using namespace dealii;

  DiscreteOperator::DiscreteOperator(const unsigned int degree)
      : fe_degree(degree)
  {
  }

  unsigned int
  DiscreteOperator::degree() const
  {
    return fe_degree;
  }

  void
  DiscreteOperator::distribute_dofs(
    const parallel::distributed::Triangulation<2> &triangulation,
    const FiniteElement<2>                        &fe)
  {
    mapping = std::make_unique<MappingQ<2>>(fe_degree);
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

  void
  DiscreteOperator::move_constrained_eigenvalues(const double eigenvalue)
  {
    for (const auto i : owned_dofs)
      if (constraints.is_constrained(i))
        mass.set(i, i, stiffness.diag_element(i) / eigenvalue);
    mass.compress(VectorOperation::insert);
  }

  const DoFHandler<2> &
  DiscreteOperator::get_dof_handler() const
  {
    return dof_handler;
  }

  const MappingQ<2> &
  DiscreteOperator::get_mapping() const
  {
    return *mapping;
  }

  const AffineConstraints<double> &
  DiscreteOperator::get_constraints() const
  {
    return constraints;
  }

  const IndexSet &
  DiscreteOperator::locally_owned_dofs() const
  {
    return owned_dofs;
  }

  const IndexSet &
  DiscreteOperator::locally_relevant_dofs() const
  {
    return relevant_dofs;
  }

  const PETScWrappers::MPI::SparseMatrix &
  DiscreteOperator::mass_matrix() const
  {
    return mass;
  }

  const PETScWrappers::MPI::SparseMatrix &
  DiscreteOperator::stiffness_matrix() const
  {
    return stiffness;
  }

  PETScWrappers::MPI::Vector
  DiscreteOperator::create_vector() const
  {
    return PETScWrappers::MPI::Vector(owned_dofs,
                                      dof_handler.get_communicator());
  }

  PETScWrappers::MPI::Vector
  DiscreteOperator::create_ghosted(
    const PETScWrappers::MPI::Vector &vector) const
  {
    PETScWrappers::MPI::Vector ghosted(owned_dofs,
                                       relevant_dofs,
                                       dof_handler.get_communicator());
    ghosted = vector;
    return ghosted;
  }
} // namespace DiskImpact
