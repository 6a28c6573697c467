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
  {
    PC pc;
    check_petsc(KSPCreate(communicator, &ksp), "KSPCreate");
    check_petsc(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
    check_petsc(PCSetType(pc, PCCHOLESKY), "PCSetType");
    if (Utilities::MPI::n_mpi_processes(communicator) == 1)
      {
        // On one rank PETSc's own Cholesky of a sequential copy solves 2-3
        // times faster than MUMPS (docs/impact-convergence.md, "One rank's
        // solver"): in blocks of the support points' components, reordered
        // by AMD, or else (or if PETSc's options choose the solver or the
        // ordering) of the scalar matrix with nested dissection.
        check_petsc(MatMPIAIJGetLocalMat(A, MAT_INITIAL_MATRIX, &sequential),
                    "MatMPIAIJGetLocalMat");
        PetscInt n_rows;
        check_petsc(MatGetSize(sequential, &n_rows, nullptr), "MatGetSize");
        if (block_size > 1 && n_rows % block_size == 0 &&
            !factorization_set_by_options())
          {
            blocked =
              std::make_unique<SymmetricBlockCopy>(sequential, block_size);
            MatDestroy(&sequential);
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
  Factorization::refactorize(const PETScWrappers::MPI::SparseMatrix &A)
  {
    if (blocked)
      {
        Mat local;
        check_petsc(MatMPIAIJGetLocalMat(A, MAT_INITIAL_MATRIX, &local),
                    "MatMPIAIJGetLocalMat");
        blocked->copy_values(local);
        MatDestroy(&local);
      }
    else if (sequential != nullptr)
      check_petsc(MatMPIAIJGetLocalMat(A, MAT_REUSE_MATRIX, &sequential),
                  "MatMPIAIJGetLocalMat");
    factorize(A);
  }

  void
  Factorization::factorize(const PETScWrappers::MPI::SparseMatrix &A)
  {
    // The same matrix object with new values: PETSc sees its pattern
    // unchanged and redoes the numeric factorization only.
    Mat factorized = blocked               ? blocked->matrix() :
                     sequential != nullptr ? sequential :
                                             static_cast<Mat>(A);
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
} // namespace DiskImpact
