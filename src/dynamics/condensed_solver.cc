#include "dynamics/condensed_solver.h"

#include "base/petsc_check.h"

#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <chrono>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The columns of @p dP with a nonzero entry (@p active) and
    /// M = S dP(:, active), from the rows of dP those columns touch.
    void
    active_jacobian_columns(const FullMatrix<double>  &S,
                            const FullMatrix<double>  &dP,
                            std::vector<unsigned int> &active,
                            FullMatrix<double>        &M)
    {
      const unsigned int        n = dP.m();
      std::vector<unsigned int> rows;
      std::vector<bool>         touched(n, false);
      active.clear();
      for (unsigned int j = 0; j < n; ++j)
        {
          bool nonzero = false;
          for (unsigned int i = 0; i < n; ++i)
            if (dP(i, j) != 0.)
              nonzero = touched[i] = true;
          if (nonzero)
            active.push_back(j);
        }
      for (unsigned int i = 0; i < n; ++i)
        if (touched[i])
          rows.push_back(i);
      FullMatrix<double> S_rows(n, rows.size()),
        dP_block(rows.size(), active.size());
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int k = 0; k < rows.size(); ++k)
          S_rows(i, k) = S(i, rows[k]);
      for (unsigned int k = 0; k < rows.size(); ++k)
        for (unsigned int l = 0; l < active.size(); ++l)
          dP_block(k, l) = dP(rows[k], active[l]);
      M.reinit(n, active.size());
      if (!active.empty())
        S_rows.mmult(M, dP_block);
    }

    /// The solution x of (I - M E_active^T) x = h: on the active rows
    /// (I - M(active, :)) x_active = h_active, then x_i = h_i + M(i, :)
    /// x_active on the others, so only the contact's share is factorized.
    Vector<double>
    solve_active_jacobian(const std::vector<unsigned int> &active,
                          const FullMatrix<double>        &M,
                          const Vector<double>            &h)
    {
      Vector<double>     x(h);
      const unsigned int a = active.size();
      if (a == 0)
        return x;
      LAPACKFullMatrix<double> block(a, a);
      Vector<double>           x_active(a);
      for (unsigned int k = 0; k < a; ++k)
        {
          for (unsigned int l = 0; l < a; ++l)
            block(k, l) = -M(active[k], l);
          block(k, k) += 1.;
          x_active(k) = h(active[k]);
        }
      block.compute_lu_factorization();
      block.solve(x_active);
      M.vmult_add(x, x_active);
      for (unsigned int k = 0; k < a; ++k)
        x(active[k]) = x_active(k);
      return x;
    }

    /// I - M E_active^T as a full matrix.
    FullMatrix<double>
    full_jacobian(const unsigned int               n,
                  const std::vector<unsigned int> &active,
                  const FullMatrix<double>        &M)
    {
      FullMatrix<double> jacobian(n, n);
      for (unsigned int i = 0; i < n; ++i)
        {
          jacobian(i, i) = 1.;
          for (unsigned int l = 0; l < active.size(); ++l)
            jacobian(i, active[l]) -= M(i, l);
        }
      return jacobian;
    }
  } // namespace

  CondensedSolver::CondensedSolver(const PETScWrappers::MPI::SparseMatrix &A,
                                   const IndexSet    &locally_owned,
                                   MPI_Comm           communicator,
                                   const unsigned int block_size)
      : CondensedSolver(std::make_shared<Factorization>(A,
                                                        communicator,
                                                        block_size),
                        locally_owned,
                        communicator)
  {
  }

  CondensedSolver::CondensedSolver(std::shared_ptr<Factorization> factorization,
                                   const IndexSet                &locally_owned,
                                   MPI_Comm                       communicator)
      : owned(locally_owned)
      , communicator(communicator)
      , factorization(std::move(factorization))
  {
  }

  const FullMatrix<double> &
  CondensedSolver::condensed_matrix() const
  {
    return s_matrix;
  }

  unsigned int
  CondensedSolver::n_factorizations() const
  {
    return 1;
  }

  unsigned int
  CondensedSolver::n_triangular_solves() const
  {
    return triangular_solves;
  }

  double
  CondensedSolver::triangular_solve_time() const
  {
    return solve_seconds;
  }

  unsigned int
  CondensedSolver::n_contact_dofs() const
  {
    return contact_positions.size();
  }

  void
  CondensedSolver::apply_inverse(const PETScWrappers::MPI::Vector &r,
                                 PETScWrappers::MPI::Vector       &y)
  {
    const auto start = std::chrono::steady_clock::now();
    factorization->solve(r, y);
    solve_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    ++triangular_solves;
  }

  void
  CondensedSolver::solve(const PETScWrappers::MPI::Vector &b,
                         PETScWrappers::MPI::Vector       &y)
  {
    apply_inverse(b, y);
  }

  void
  CondensedSolver::set_observed_dofs(
    const std::vector<types::global_dof_index> &observed)
  {
    observed_dofs = observed;
    owned_positions.clear();
    owned_observed_dofs.clear();
    for (unsigned int i = 0; i < observed_dofs.size(); ++i)
      if (owned.is_element(observed_dofs[i]))
        {
          owned_positions.push_back(i);
          owned_observed_dofs.push_back(observed_dofs[i]);
        }
    // C is a subset of D: room for all its columns, so that a growing C
    // never copies the columns it has.
    columns.reserve(observed_dofs.size());
    observed_columns.reserve(observed_dofs.size());
  }

  Vector<double>
  CondensedSolver::observe(const PETScWrappers::MPI::Vector &v) const
  {
    std::vector<double> owned_values(owned_observed_dofs.size());
    v.extract_subvector_to(owned_observed_dofs, owned_values);
    std::vector<double> values(observed_dofs.size(), 0.);
    for (unsigned int k = 0; k < owned_positions.size(); ++k)
      values[owned_positions[k]] = owned_values[k];
    if (Utilities::MPI::n_mpi_processes(communicator) > 1)
      Utilities::MPI::sum(values, communicator, values);
    return Vector<double>(values.begin(), values.end());
  }

  void
  CondensedSolver::add_dofs(const std::vector<unsigned int> &positions)
  {
    // The new columns X e_i, all in one solve.
    std::vector<PETScWrappers::MPI::Vector> units, new_columns;
    for (const unsigned int position : positions)
      {
        const auto dof = observed_dofs[position];
        contact_positions.push_back(position);
        units.emplace_back(owned, communicator);
        if (owned.is_element(dof))
          units.back()(dof) = 1.;
        units.back().compress(VectorOperation::insert);
        new_columns.emplace_back(owned, communicator);
      }
    const auto start = std::chrono::steady_clock::now();
    factorization->solve(units, new_columns);
    solve_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    triangular_solves += positions.size();
    for (auto &column : new_columns)
      {
        columns.push_back(std::move(column));
        observed_columns.push_back(observe(columns.back()));
      }
    // S = E_C^T X from the columns' values on D.
    const unsigned int n = contact_positions.size();
    s_matrix.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        s_matrix(i, j) = 0.5 * (observed_columns[j][contact_positions[i]] +
                                observed_columns[i][contact_positions[j]]);
  }

  Vector<double>
  CondensedSolver::observed_response(const Vector<double> &P) const
  {
    Vector<double> response(observed_dofs.size());
    for (unsigned int j = 0; j < P.size(); ++j)
      response.add(P[j], observed_columns[j]);
    return response;
  }

  void
  CondensedSolver::add_forces(const Vector<double>       &P,
                              PETScWrappers::MPI::Vector &x) const
  {
    for (unsigned int j = 0; j < P.size(); ++j)
      {
        const auto dof = observed_dofs[contact_positions[j]];
        if (owned.is_element(dof))
          x(dof) += P[j];
      }
    x.compress(VectorOperation::add);
  }

  void
  CondensedSolver::add_columns(const Vector<double>       &P,
                               PETScWrappers::MPI::Vector &x) const
  {
    // One pass over x for all columns.
    std::vector<PetscScalar> weights;
    std::vector<Vec>         vectors;
    for (unsigned int j = 0; j < P.size(); ++j)
      if (P[j] != 0.)
        {
          weights.push_back(P[j]);
          vectors.push_back(columns[j]);
        }
    if (!weights.empty())
      check_petsc(VecMAXPY(x, weights.size(), weights.data(), vectors.data()),
                  "VecMAXPY");
  }

  bool
  CondensedSolver::solve_condensed(const Vector<double> &y_C,
                                   const Force          &force,
                                   const double          tolerance,
                                   const unsigned int    max_iterations,
                                   Vector<double>       &u_C,
                                   unsigned int         &iterations,
                                   const bool euclidean_fallback) const
  {
    return solve_condensed(s_matrix,
                           y_C,
                           force,
                           tolerance,
                           max_iterations,
                           u_C,
                           iterations,
                           euclidean_fallback);
  }

  bool
  CondensedSolver::solve_condensed(const FullMatrix<double> &S,
                                   const Vector<double>     &y_C,
                                   const Force              &force,
                                   const double              tolerance,
                                   const unsigned int        max_iterations,
                                   Vector<double>           &u_C,
                                   unsigned int             &iterations,
                                   const bool                euclidean_fallback)
  {
    const unsigned int n = y_C.size();
    // h(u) = u - y_C - S P(u) and |h|, with the Jacobian I - S dP/du.
    Vector<double> h(n), sp(n);
    // Only the columns `active` of dP/du are nonzero (points in contact):
    // the Jacobian is I - M E_active^T with M = S dP/du(:, active).
    std::vector<unsigned int> active;
    FullMatrix<double>        M;
    auto residual = [&](const Vector<double> &u, bool with_jac) {
      auto [P, dP] = force(u);
      S.vmult(sp, P);
      h = u;
      h -= y_C;
      h -= sp;
      if (with_jac)
        active_jacobian_columns(S, dP, active, M);
      return h.linfty_norm();
    };
    double norm = residual(u_C, true);
    for (iterations = 0; iterations < max_iterations; ++iterations)
      {
        if (norm <= tolerance)
          return true;
        Vector<double> step  = solve_active_jacobian(active, M, h);
        const double norm2 = h.l2_norm();
        // Backtracking: the penalty's kinks can make a full step overshoot.
        double         length = 1.;
        Vector<double> trial(n);
        bool           decreased = false;
        for (unsigned int cut = 0; cut < 20 && !decreased; ++cut, length *= 0.5)
          {
            trial = u_C;
            trial.add(-length, step);
            decreased = residual(trial, false) < norm;
          }
        // No decrease along the Newton direction: the residual is at its
        // rounding floor, which the stiff Jacobian I - S dP/du raises above
        // eps |u_C|. Converged if u_C's error, which the Newton step
        // estimates, is within the tolerance; otherwise a failure.
        if (!decreased &&
            (step.linfty_norm() <= tolerance || !euclidean_fallback))
          return step.linfty_norm() <= tolerance;
        // Under friction the return mapping's kinks can leave the largest
        // component without a decrease along the Newton direction: then
        // the Euclidean norm decides.
        length = 1.;
        for (unsigned int cut = 0; cut < 30 && !decreased; ++cut, length *= 0.5)
          {
            trial = u_C;
            trial.add(-length, step);
            residual(trial, false);
            decreased = h.l2_norm() < norm2;
          }
        // At a kink of the return mapping the Newton direction need not
        // descend at all: then Levenberg-Marquardt steps
        // (J^T J + lambda I) d = J^T h, lambda growing until |h| falls,
        // which turn toward the residual's steepest descent.
        if (!decreased)
          {
            residual(u_C, false);
            const Vector<double> h0(h);
            const auto           jacobian = full_jacobian(n, active, M);
            FullMatrix<double>   normal(n, n);
            jacobian.Tmmult(normal, jacobian);
            Vector<double> gradient(n);
            jacobian.Tvmult(gradient, h0);
            double scale = 0.;
            for (unsigned int i = 0; i < n; ++i)
              scale = std::max(scale, normal(i, i));
            for (double lambda = 1e-8 * scale;
                 lambda <= 1e8 * scale && !decreased;
                 lambda *= 10.)
              {
                LAPACKFullMatrix<double> damped(n, n);
                damped = normal;
                for (unsigned int i = 0; i < n; ++i)
                  damped(i, i) += lambda;
                damped.compute_lu_factorization();
                step = gradient;
                damped.solve(step);
                trial = u_C;
                trial -= step;
                residual(trial, false);
                decreased = h.l2_norm() < norm2;
              }
          }
        if (!decreased)
          return false;
        u_C  = trial;
        norm = residual(u_C, true);
      }
    return norm <= tolerance;
  }
} // namespace DiskImpact
