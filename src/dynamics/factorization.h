#pragma once

#include "dynamics/symmetric_block_copy.h"

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <petscksp.h>

#include <memory>
#include <vector>

namespace DiskImpact
{
  /// One term c A of a sum of matrices, with how A's pattern lies within the
  /// first term's (for PETSc's MatAXPY).
  struct MatrixTerm
  {
    double                                          coefficient;
    const dealii::PETScWrappers::MPI::SparseMatrix *matrix;
    MatStructure pattern = SUBSET_NONZERO_PATTERN;
  };

  /// The symmetric matrix sum_i c_i A_i, the first term's pattern holding
  /// the others': the effective matrix c_K K + c_M M (+ c_D D) of an
  /// implicit step.
  using MatrixSum = std::vector<MatrixTerm>;

  /**
   * The Cholesky factorization of a symmetric positive definite matrix A
   * whose sparsity pattern stays fixed: MUMPS on several ranks; on one,
   * PETSc's own, of a copy in blocks of @p block_size consecutive rows
   * (SymmetricBlockCopy) if that is > 1, else of the scalar matrix with
   * nested dissection. refactorize() takes new values on the same pattern
   * and keeps what depends on the pattern alone: the block copy's order
   * and allocation and the symbolic factorization. The runs of a study on
   * one mesh differ in their time step, so in A's values only
   * (docs/theory/impact-method.md, "The condensed contact solve").
   *
   * A may be given as a MatrixSum. The block copy takes the sum of the
   * terms' values directly; otherwise the factorization sums them into a
   * matrix of its own (docs/theory/impact-method.md).
   */
  class Factorization
  {
  public:
    /// With @p mumps_everywhere MUMPS on one rank too: on a
    /// three-dimensional mesh its nested-dissection ordering makes it
    /// several times faster than the block copy.
    Factorization(const MatrixSum &A,
                  MPI_Comm         communicator,
                  unsigned int     block_size       = 1,
                  bool             mumps_everywhere = false);
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
    refactorize(const MatrixSum &A);

    /// y = A^{-1} r. Collective.
    void
    solve(const dealii::PETScWrappers::MPI::Vector &r,
          dealii::PETScWrappers::MPI::Vector       &y);

    /// y_k = A^{-1} r_k for all k at once (MUMPS solves the right-hand
    /// sides in blocks, several times faster than one by one; the other
    /// solvers one by one). Collective.
    void
    solve(const std::vector<dealii::PETScWrappers::MPI::Vector> &r,
          std::vector<dealii::PETScWrappers::MPI::Vector>       &y);

  private:
    /// Give PETSc the matrix it factorizes (the block copy, the sequential
    /// copy or the sum of @p A itself, the same object as before if there
    /// was one) with @p A's values, and factorize it.
    void
    factorize(const MatrixSum &A);

    /// The sum of @p A's terms as one matrix: the first term's matrix if it
    /// is the only one, with coefficient 1, else @p sum.
    const dealii::PETScWrappers::MPI::SparseMatrix &
    summed(const MatrixSum &A);

    /// PETSc's own Cholesky on one rank (else MUMPS).
    bool own_cholesky;
    KSP  ksp = nullptr;
    /// A's terms summed, where they are not the first term's matrix alone
    /// and no block copy sums them.
    dealii::PETScWrappers::MPI::SparseMatrix sum;
    /// A's sequential copy, factorized instead of A on one rank.
    Mat sequential = nullptr;
    /// Or its copy in blocks of @p block_size rows, with the solve's
    /// right-hand side and solution in the copy's order.
    std::unique_ptr<SymmetricBlockCopy> blocked;
    Vec                                 copy_order_rhs      = nullptr;
    Vec                                 copy_order_solution = nullptr;
  };
} // namespace DiskImpact
