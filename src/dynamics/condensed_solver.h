#pragma once

#include "dynamics/factorization.h"

#include <deal.II/base/index_set.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace DiskImpact
{
  /**
   * Solves A u = b + E_C P(u_C) for a fixed symmetric positive definite A
   * and a nonlinear force P that acts on a few DoFs C only (the contact),
   * by static condensation: with y = A^{-1} b, X = A^{-1} E_C and
   * S = E_C^T X,
   *
   *   u = y + X P(u_C),   where   u_C = y_C + S P(u_C)
   *
   * is a small dense system, solved by Newton's method. A is factorized
   * once (Factorization) for the solver's life; a column of X costs one
   * solve when its DoF joins C; a step then costs one solve with A, the
   * dense Newton and |C| vector updates.
   */
  class CondensedSolver
  {
  public:
    CondensedSolver(const dealii::PETScWrappers::MPI::SparseMatrix &A,
                    const dealii::IndexSet &locally_owned,
                    MPI_Comm                communicator,
                    unsigned int            block_size = 1);
    /// With A's factorization, made (or refactorized) for A elsewhere.
    CondensedSolver(std::shared_ptr<Factorization> factorization,
                    const dealii::IndexSet        &locally_owned,
                    MPI_Comm                       communicator);
    CondensedSolver(const CondensedSolver &) = delete;
    CondensedSolver &
    operator=(const CondensedSolver &) = delete;

    /// The DoFs D at which observe() reports values; C will be a subset.
    void
    set_observed_dofs(
      const std::vector<dealii::types::global_dof_index> &observed);

    /// The values of @p v on D, on every rank.
    dealii::Vector<double>
    observe(const dealii::PETScWrappers::MPI::Vector &v) const;

    /// Append the DoFs at @p positions of D to C (the same list on every
    /// rank): one solve each for its column of X.
    void
    add_dofs(const std::vector<unsigned int> &positions);

    /// X P on D: the change of the observed values by the force P on C.
    dealii::Vector<double>
    observed_response(const dealii::Vector<double> &P) const;

    /// y = A^{-1} b.
    void
    solve(const dealii::PETScWrappers::MPI::Vector &b,
          dealii::PETScWrappers::MPI::Vector       &y);

    /// S = E_C^T X on C (symmetrized), the matrix of solve_condensed().
    const dealii::FullMatrix<double> &
    condensed_matrix() const;

    /// x += E_C P: the force P on C as a vector of all DoFs. Collective.
    void
    add_forces(const dealii::Vector<double>       &P,
               dealii::PETScWrappers::MPI::Vector &x) const;

    /// x += X P.
    void
    add_columns(const dealii::Vector<double>       &P,
                dealii::PETScWrappers::MPI::Vector &x) const;

    /// The force on C and its Jacobian at u_C.
    using Force = std::function<
      std::pair<dealii::Vector<double>, dealii::FullMatrix<double>>(
        const dealii::Vector<double> &u_C)>;

    /**
     * Newton's method for u_C = y_C + S P(u_C) from @p u_C, with a
     * backtracking line search on |u_C - y_C - S P(u_C)|; true if that
     * falls below @p tolerance (in max norm) within @p max_iterations, or
     * if it stops decreasing (its rounding floor) with a Newton step below
     * @p tolerance. With @p euclidean_fallback (friction, whose kinks can
     * leave the largest component without a decrease) a step the max norm
     * refuses is tried on the Euclidean norm before giving up.
     * Identical on every rank (no communication).
     */
    bool
    solve_condensed(const dealii::Vector<double> &y_C,
                    const Force                  &force,
                    double                        tolerance,
                    unsigned int                  max_iterations,
                    dealii::Vector<double>       &u_C,
                    unsigned int                 &iterations,
                    bool euclidean_fallback = false) const;
    /// The same Newton's method on the system u = y + @p S P(u) of any
    /// size (C with unknowns of the contact's own appended).
    static bool
    solve_condensed(const dealii::FullMatrix<double> &S,
                    const dealii::Vector<double>     &y,
                    const Force                      &force,
                    double                            tolerance,
                    unsigned int                      max_iterations,
                    dealii::Vector<double>           &u,
                    unsigned int                     &iterations,
                    bool                              euclidean_fallback);

    /// Factorizations of A made for this solver: one.
    unsigned int
    n_factorizations() const;
    /// Solves with A: one per solve() plus one per column of X (the columns
    /// added together solved as one block, Factorization::solve()).
    unsigned int
    n_triangular_solves() const;
    /// |C|.
    unsigned int
    n_contact_dofs() const;
    /// Wall time spent in solves with A [s].
    double
    triangular_solve_time() const;

  private:
    void
    apply_inverse(const dealii::PETScWrappers::MPI::Vector &r,
                  dealii::PETScWrappers::MPI::Vector       &y);

    dealii::IndexSet                             owned;
    MPI_Comm                                     communicator;
    std::shared_ptr<Factorization>               factorization;
    std::vector<dealii::types::global_dof_index> observed_dofs;
    /// The positions in D of the DoFs this rank owns, and those DoFs.
    std::vector<unsigned int>                    owned_positions;
    std::vector<dealii::types::global_dof_index> owned_observed_dofs;
    /// C as positions in D, their columns of X and those on D.
    std::vector<unsigned int>                       contact_positions;
    std::vector<dealii::PETScWrappers::MPI::Vector> columns;
    std::vector<dealii::Vector<double>>             observed_columns;
    /// S = E_C^T X.
    dealii::FullMatrix<double> s_matrix;
    unsigned int               triangular_solves = 0;
    double                     solve_seconds     = 0.;
  };
} // namespace DiskImpact
