#pragma once

#include "dynamics/symmetric_block_copy.h"

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <petscksp.h>

#include <memory>

namespace DiskImpact
{
  /**
   * The Cholesky factorization of a symmetric positive definite matrix A
   * whose sparsity pattern stays fixed: MUMPS on several ranks; on one,
   * PETSc's own, of a copy in blocks of @p block_size consecutive rows
   * (SymmetricBlockCopy) if that is > 1, else of the scalar matrix with
   * nested dissection. refactorize() takes new values on the same pattern
   * and keeps what depends on the pattern alone: the block copy's order
   * and allocation and the symbolic factorization. The runs of a study on
   * one mesh differ in their time step, so in A's values only
   * (docs/impact-convergence.md, "One factorization per mesh").
   */
  class Factorization
  {
  public:
    Factorization(const dealii::PETScWrappers::MPI::SparseMatrix &A,
                  MPI_Comm                                        communicator,
                  unsigned int block_size = 1);
    ~Factorization();
    Factorization(const Factorization &) = delete;
    Factorization &
    operator=(const Factorization &) = delete;

    /// Factorize @p A, whose pattern must be the first matrix's, afresh:
    /// the numeric factorization only.
    void
    refactorize(const dealii::PETScWrappers::MPI::SparseMatrix &A);

    /// y = A^{-1} r. Collective.
    void
    solve(const dealii::PETScWrappers::MPI::Vector &r,
          dealii::PETScWrappers::MPI::Vector       &y);

  private:
    /// Give PETSc the matrix it factorizes (the block copy, the sequential
    /// copy or @p A itself, the same object as before if there was one)
    /// and factorize it.
    void
    factorize(const dealii::PETScWrappers::MPI::SparseMatrix &A);

    KSP ksp = nullptr;
    /// A's sequential copy, factorized instead of A on one rank.
    Mat sequential = nullptr;
    /// Or its copy in blocks of @p block_size rows, with the solve's
    /// right-hand side and solution in the copy's order.
    std::unique_ptr<SymmetricBlockCopy> blocked;
    Vec                                 copy_order_rhs      = nullptr;
    Vec                                 copy_order_solution = nullptr;
  };
} // namespace DiskImpact
