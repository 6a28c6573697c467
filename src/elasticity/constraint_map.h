#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <mpi.h>

namespace DiskImpact
{
  /**
   * The constraints of a discretization (hanging nodes, symmetry planes) as
   * one sparse matrix and one mask, for the time loop:
   *  - distribute(): x <- T x + g, where T is the identity on the
   *    unconstrained rows and holds the weights of each constrained DoF's
   *    line on its row, g the inhomogeneities; one product, in place of
   *    AffineConstraints::distribute(), which reads and writes a PETSc
   *    vector entry by entry;
   *  - set_zero(): x <- x .* m, m zero on the constrained DoFs (zeroed():
   *    into another vector).
   * Same results as the AffineConstraints it is built from (closed, so a
   * line holds only unconstrained DoFs).
   */
  class ConstraintMap
  {
  public:
    /// From @p constraints (with the lines of the locally owned DoFs).
    /// Collective.
    ConstraintMap(const dealii::AffineConstraints<double> &constraints,
                  const dealii::IndexSet                  &locally_owned,
                  MPI_Comm                                 communicator);

    /// The constrained entries of @p x from the others. Collective.
    void
    distribute(dealii::PETScWrappers::MPI::Vector &x) const;

    /// The constrained entries of @p x set to zero.
    void
    set_zero(dealii::PETScWrappers::MPI::Vector &x) const;

    /// @p result = @p x with its constrained entries zero (one pass).
    void
    zeroed(const dealii::PETScWrappers::MPI::Vector &x,
           dealii::PETScWrappers::MPI::Vector       &result) const;

  private:
    dealii::PETScWrappers::MPI::SparseMatrix   map;
    dealii::PETScWrappers::MPI::Vector         mask, inhomogeneity;
    mutable dealii::PETScWrappers::MPI::Vector mapped;
  };
} // namespace DiskImpact
