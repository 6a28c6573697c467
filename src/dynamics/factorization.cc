#include "dynamics/factorization.h"

#include "base/petsc_check.h"

#include <deal.II/base/mpi.h>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// Whether PETSc's options choose the solver or the ordering: then they
    /// apply to the scalar matrix, as they say.
    bool
    factorization_set_by_options()
    {
      PetscBool solver_set, ordering_set;
      check_petsc(PetscOptionsHasName(nullptr,
                                      nullptr,
                                      "-pc_factor_mat_solver_type",
                                      &solver_set),
                  "PetscOptionsHasName");
      check_petsc(PetscOptionsHasName(nullptr,
                                      nullptr,
                                      "-pc_factor_mat_ordering_type",
                                      &ordering_set),
                  "PetscOptionsHasName");
      return solver_set || ordering_set;
    }
  } // namespace

  Factorization::Factorization(const PETScWrappers::MPI::SparseMatrix &A,
                               MPI_Comm           communicator,
                               const unsigned int block_size)
      : Factorization(MatrixSum{{1., &A}}, communicator, block_size)
  {
  }

  Factorization::Factorization(const MatrixSum   &A,
                               MPI_Comm           communicator,
                               const unsigned int block_size,
                               const bool         mumps_everywhere)
      : own_cholesky(Utilities::MPI::n_mpi_processes(communicator) == 1 &&
                     !mumps_everywhere)
  {
    PC pc;
    check_petsc(KSPCreate(communicator, &ksp), "KSPCreate");
    check_petsc(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
    check_petsc(PCSetType(pc, PCCHOLESKY), "PCSetType");
    if (own_cholesky)
      {
        // On one rank PETSc's own Cholesky of a sequential copy solves 2-3
        // times faster than MUMPS (docs/theory/impact-method.md, "The
        // condensed contact solve"): in blocks of the support points'
        // components, reordered by AMD, or else (or if PETSc's options choose
        // the solver or the ordering) of the scalar matrix with nested
        // dissection.
        const auto &first = *A.front().matrix;
        if (block_size > 1 && first.m() % block_size == 0 &&
            !factorization_set_by_options())
          {
            // The block copy's pattern and order from the first term's.
            Mat pattern;
            check_petsc(MatMPIAIJGetLocalMat(first,
                                             MAT_INITIAL_MATRIX,
                                             &pattern),
                        "MatMPIAIJGetLocalMat");
            blocked = std::make_unique<SymmetricBlockCopy>(pattern, block_size);
            MatDestroy(&pattern);
            check_petsc(MatCreateVecs(blocked->matrix(),
                                      &copy_order_rhs,
                                      &copy_order_solution),
                        "MatCreateVecs");
          }
        check_petsc(PCFactorSetMatSolverType(pc, MATSOLVERPETSC),
                    "PCFactorSetMatSolverType");
        check_petsc(PCFactorSetMatOrderingType(pc,
                                               blocked ? MATORDERINGNATURAL :
                                                         MATORDERINGND),
                    "PCFactorSetMatOrderingType");
      }
    else
      check_petsc(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS),
                  "PCFactorSetMatSolverType");
    // PETSc's options (e.g. -pc_factor_mat_ordering_type, or
    // -mat_mumps_icntl_7 for MUMPS's ordering) apply.
    check_petsc(KSPSetFromOptions(ksp), "KSPSetFromOptions");
    factorize(A);
  }

  Factorization::~Factorization()
  {
    if (ksp != nullptr)
      KSPDestroy(&ksp);
    if (sequential != nullptr)
      MatDestroy(&sequential);
    if (copy_order_rhs != nullptr)
      VecDestroy(&copy_order_rhs);
    if (copy_order_solution != nullptr)
      VecDestroy(&copy_order_solution);
  }

  void
  Factorization::refactorize(const MatrixSum &A)
  {
    factorize(A);
  }

  const PETScWrappers::MPI::SparseMatrix &
  Factorization::summed(const MatrixSum &A)
  {
    const auto &first = *A.front().matrix;
    if (A.size() == 1 && A.front().coefficient == 1.)
      return first;
    if (sum.m() == 0)
      sum.reinit(first);
    sum.copy_from(first);
    sum *= A.front().coefficient;
    // PETSc's sum for a known pattern: deal.II's add() assumes a different
    // one and rebuilds the matrix.
    for (unsigned int k = 1; k < A.size(); ++k)
      check_petsc(MatAXPY(sum.petsc_matrix(),
                          A[k].coefficient,
                          static_cast<Mat>(*A[k].matrix),
                          A[k].pattern),
                  "MatAXPY");
    return sum;
  }

  void
  Factorization::factorize(const MatrixSum &A)
  {
    // The same matrix object with new values: PETSc sees its pattern
    // unchanged and redoes the numeric factorization only.
    Mat factorized;
    if (blocked)
      {
        // The terms' values summed into the copy: on one rank a matrix's
        // local part is its own diagonal block, no copy.
        std::vector<std::pair<PetscScalar, Mat>> local_terms;
        for (const auto &term : A)
          {
            Mat local;
            check_petsc(MatMPIAIJGetLocalMat(*term.matrix,
                                             MAT_INITIAL_MATRIX,
                                             &local),
                        "MatMPIAIJGetLocalMat");
            local_terms.emplace_back(term.coefficient, local);
          }
        blocked->copy_values(local_terms);
        for (auto &term : local_terms)
          MatDestroy(&term.second);
        factorized = blocked->matrix();
      }
    else if (own_cholesky)
      {
        check_petsc(MatMPIAIJGetLocalMat(summed(A),
                                         sequential != nullptr ?
                                           MAT_REUSE_MATRIX :
                                           MAT_INITIAL_MATRIX,
                                         &sequential),
                    "MatMPIAIJGetLocalMat");
        factorized = sequential;
      }
    else
      factorized = summed(A);
    check_petsc(KSPSetOperators(ksp, factorized, factorized),
                "KSPSetOperators");
    check_petsc(KSPSetUp(ksp), "KSPSetUp");
  }

  void
  Factorization::solve(const PETScWrappers::MPI::Vector &r,
                       PETScWrappers::MPI::Vector       &y)
  {
    if (blocked)
      {
        blocked->to_copy_order(r, copy_order_rhs);
        check_petsc(KSPSolve(ksp, copy_order_rhs, copy_order_solution),
                    "KSPSolve");
        blocked->from_copy_order(copy_order_solution, y);
      }
    else
      check_petsc(KSPSolve(ksp, r, y), "KSPSolve");
  }

  void
  Factorization::solve(const std::vector<PETScWrappers::MPI::Vector> &r,
                       std::vector<PETScWrappers::MPI::Vector>       &y)
  {
    AssertDimension(r.size(), y.size());
    if (own_cholesky || r.size() < 2)
      {
        for (unsigned int k = 0; k < r.size(); ++k)
          solve(r[k], y[k]);
        return;
      }
    // The right-hand sides as the columns of a dense matrix B, X = A^{-1} B
    // by the factor's MatMatSolve.
    PC  pc;
    Mat factor, B, X;
    check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
    check_petsc(PCFactorGetMatrix(pc, &factor), "PCFactorGetMatrix");
    const auto local_rows =
      static_cast<PetscInt>(r.front().locally_owned_size());
    const auto     n_rows       = static_cast<PetscInt>(r.front().size());
    const auto     n_columns    = static_cast<PetscInt>(r.size());
    const MPI_Comm communicator = r.front().get_mpi_communicator();
    for (Mat *dense : {&B, &X})
      check_petsc(MatCreateDense(communicator,
                                 local_rows,
                                 PETSC_DECIDE,
                                 n_rows,
                                 n_columns,
                                 nullptr,
                                 dense),
                  "MatCreateDense");
    for (PetscInt k = 0; k < n_columns; ++k)
      {
        Vec column;
        check_petsc(MatDenseGetColumnVecWrite(B, k, &column),
                    "MatDenseGetColumnVecWrite");
        check_petsc(VecCopy(r[k], column), "VecCopy");
        check_petsc(MatDenseRestoreColumnVecWrite(B, k, &column),
                    "MatDenseRestoreColumnVecWrite");
      }
    check_petsc(MatMatSolve(factor, B, X), "MatMatSolve");
    for (PetscInt k = 0; k < n_columns; ++k)
      {
        Vec column;
        check_petsc(MatDenseGetColumnVecRead(X, k, &column),
                    "MatDenseGetColumnVecRead");
        check_petsc(VecCopy(column, y[k]), "VecCopy");
        check_petsc(MatDenseRestoreColumnVecRead(X, k, &column),
                    "MatDenseRestoreColumnVecRead");
      }
    MatDestroy(&B);
    MatDestroy(&X);
  }
} // namespace DiskImpact
