#include "dynamics/low_rank_corrected_solver.h"

#include "base/petsc_check.h"

#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>
#include <string>

namespace DiskImpact
{
  using namespace dealii;

  LowRankCorrectedSolver::LowRankCorrectedSolver(
    const PETScWrappers::MPI::SparseMatrix &A,
    const IndexSet                         &locally_owned,
    MPI_Comm                                communicator)
      : owned(locally_owned)
      , communicator(communicator)
  {
    PC pc;
    check_petsc(KSPCreate(communicator, &ksp), "KSPCreate");
    check_petsc(KSPSetOperators(ksp, A, A), "KSPSetOperators");
    check_petsc(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
    check_petsc(PCSetType(pc, PCCHOLESKY), "PCSetType");
    check_petsc(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS),
                "PCFactorSetMatSolverType");
    // PETSc's options (e.g. -mat_mumps_icntl_7 for the ordering) apply.
    check_petsc(KSPSetFromOptions(ksp), "KSPSetFromOptions");
    check_petsc(KSPSetUp(ksp), "KSPSetUp");
    ++factorizations;
  }

  LowRankCorrectedSolver::~LowRankCorrectedSolver()
  {
    if (ksp != nullptr)
      KSPDestroy(&ksp);
  }

  unsigned int
  LowRankCorrectedSolver::n_factorizations() const
  {
    return factorizations;
  }

  unsigned int
  LowRankCorrectedSolver::n_triangular_solves() const
  {
    return triangular_solves;
  }

  double
  LowRankCorrectedSolver::triangular_solve_time() const
  {
    return solve_seconds;
  }

  unsigned int
  LowRankCorrectedSolver::n_contact_dofs() const
  {
    return contact_dofs.size();
  }

  void
  LowRankCorrectedSolver::apply_inverse(const PETScWrappers::MPI::Vector &r,
                                        PETScWrappers::MPI::Vector       &y)
  {
    const auto start = std::chrono::steady_clock::now();
    check_petsc(KSPSolve(ksp, r, y), "KSPSolve");
    solve_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    ++triangular_solves;
  }

  std::vector<double>
  LowRankCorrectedSolver::values_on_contact_dofs(
    const PETScWrappers::MPI::Vector &v) const
  {
    std::vector<double> values(contact_dofs.size(), 0.);
    for (unsigned int i = 0; i < contact_dofs.size(); ++i)
      if (owned.is_element(contact_dofs[i]))
        values[i] = v(contact_dofs[i]);
    Utilities::MPI::sum(values, communicator, values);
    return values;
  }

  void
  LowRankCorrectedSolver::extend_contact_dofs(
    const std::vector<RankOneTerm> &terms)
  {
    std::vector<types::global_dof_index> local;
    for (const auto &term : terms)
      for (const auto &entry : term.entries)
        if (position.find(entry.first) == position.end())
          local.push_back(entry.first);
    std::set<types::global_dof_index> added;
    for (const auto &part : Utilities::MPI::all_gather(communicator, local))
      added.insert(part.begin(), part.end());
    if (added.empty())
      return;

    const unsigned int n_old = contact_dofs.size();
    for (const auto dof : added)
      {
        position[dof] = contact_dofs.size();
        contact_dofs.push_back(dof);
        PETScWrappers::MPI::Vector unit(owned, communicator);
        if (owned.is_element(dof))
          unit(dof) = 1.;
        unit.compress(VectorOperation::insert);
        columns.emplace_back(owned, communicator);
        apply_inverse(unit, columns.back());
      }
    // S = E_C^T X, symmetric: new columns give the new rows too.
    const unsigned int n = contact_dofs.size();
    FullMatrix<double> s(n, n);
    for (unsigned int i = 0; i < n_old; ++i)
      for (unsigned int j = 0; j < n_old; ++j)
        s(i, j) = s_matrix(i, j);
    for (unsigned int j = n_old; j < n; ++j)
      {
        const auto values = values_on_contact_dofs(columns[j]);
        for (unsigned int i = 0; i < n; ++i)
          s(i, j) = s(j, i) = values[i];
      }
    s_matrix = std::move(s);
  }

  void
  LowRankCorrectedSolver::solve(const std::vector<RankOneTerm>   &terms,
                                const PETScWrappers::MPI::Vector &r,
                                PETScWrappers::MPI::Vector       &x)
  {
    extend_contact_dofs(terms);
    apply_inverse(r, x);
    const unsigned int n = contact_dofs.size();
    if (n == 0)
      return;

    // G = sum w b b^T on C, summed over the ranks' terms.
    std::vector<double> g(n * n, 0.);
    for (const auto &term : terms)
      for (const auto &[i, bi] : term.entries)
        for (const auto &[j, bj] : term.entries)
          g[position[i] * n + position[j]] += term.weight * bi * bj;
    Utilities::MPI::sum(g, communicator, g);
    if (std::all_of(g.begin(), g.end(), [](double v) { return v == 0.; }))
      return;

    // (I + G S) z = G y_C
    const auto               y_c = values_on_contact_dofs(x);
    LAPACKFullMatrix<double> system(n, n);
    Vector<double>           z(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        for (unsigned int j = 0; j < n; ++j)
          {
            double gs = 0.;
            for (unsigned int k = 0; k < n; ++k)
              gs += g[i * n + k] * s_matrix(k, j);
            system(i, j) = (i == j) + gs;
            z(i) += g[i * n + j] * y_c[j];
          }
      }
    system.compute_lu_factorization();
    system.solve(z);
    for (unsigned int j = 0; j < n; ++j)
      if (z(j) != 0.)
        x.add(-z(j), columns[j]);
  }
} // namespace DiskImpact
