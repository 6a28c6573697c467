#pragma once

#include "contact/contact_operator.h"

#include <deal.II/base/index_set.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <petscksp.h>

#include <map>
#include <vector>

namespace DiskImpact
{
  /**
   * Solves (A + sum_q w_q b_q b_q^T) x = r for a fixed symmetric positive
   * definite A and a changing low-rank part (the contact tangent), with one
   * factorization of A (MUMPS Cholesky) for its whole life:
   * by the Sherman-Morrison-Woodbury identity, with C the DoFs the rank-one
   * terms touch, X = A^{-1} E_C, S = E_C^T X and G = sum w b b^T on C,
   *
   *   x = y - X (I + G S)^{-1} G y_C,   y = A^{-1} r.
   *
   * The columns of X are computed once, when a DoF first enters C; a solve
   * then costs one pair of triangular solves plus a dense system of the
   * size of C.
   */
  class LowRankCorrectedSolver
  {
  public:
    LowRankCorrectedSolver(const dealii::PETScWrappers::MPI::SparseMatrix &A,
                           const dealii::IndexSet &locally_owned,
                           MPI_Comm                communicator);
    ~LowRankCorrectedSolver();
    LowRankCorrectedSolver(const LowRankCorrectedSolver &) = delete;
    LowRankCorrectedSolver &
    operator=(const LowRankCorrectedSolver &) = delete;

    /// x = (A + sum of @p terms)^{-1} r; @p terms from all ranks count.
    void
    solve(const std::vector<RankOneTerm>           &terms,
          const dealii::PETScWrappers::MPI::Vector &r,
          dealii::PETScWrappers::MPI::Vector       &x);

    unsigned int
    n_factorizations() const;
    /// Solves with A: one per solve() plus one per column of X.
    unsigned int
    n_triangular_solves() const;
    /// Size of C.
    unsigned int
    n_contact_dofs() const;
    /// Wall time spent in solves with A [s].
    double
    triangular_solve_time() const;

  private:
    void
    apply_inverse(const dealii::PETScWrappers::MPI::Vector &r,
                  dealii::PETScWrappers::MPI::Vector       &y);
    /// Values of a distributed vector at the DoFs of C, on every rank.
    std::vector<double>
    values_on_contact_dofs(const dealii::PETScWrappers::MPI::Vector &v) const;
    /// Add the DoFs of @p terms (all ranks) not yet in C.
    void
    extend_contact_dofs(const std::vector<RankOneTerm> &terms);

    dealii::IndexSet                                        owned;
    MPI_Comm                                                communicator;
    KSP                                                     ksp = nullptr;
    std::vector<dealii::types::global_dof_index>            contact_dofs;
    std::map<dealii::types::global_dof_index, unsigned int> position;
    std::vector<dealii::PETScWrappers::MPI::Vector>         columns;
    dealii::FullMatrix<double>                              s_matrix;
    unsigned int                                            factorizations = 0;
    unsigned int triangular_solves                                         = 0;
    double       solve_seconds                                             = 0.;
  };
} // namespace DiskImpact
