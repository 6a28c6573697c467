#pragma once

#include "elasticity/constraint_map.h"

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <petscmat.h>

#include <utility>
#include <vector>

namespace DiskImpact
{
  /**
   * The product with the mass matrix M of a field whose constrained entries
   * are zero, for the time loop. The mass form couples equal components
   * only, with the same scalar weights for both: on the unconstrained rows
   * and columns M = m ⊗ I2, with the DoFs of each support point numbered
   * together (x, y). So one scalar matrix m, applied to both components at
   * once by PETSc's MAIJ format, reads half the entries and indices that M
   * does (docs/theory/impact-method.md).
   *
   * m is read off M itself, and only if M has that structure exactly (the
   * x-x and y-y entries equal to rounding where both are unconstrained, no
   * entry that couples x with y, every rank's rows whole points); else the
   * product is M's own.
   */
  class InterleavedMass
  {
  public:
    /// From the assembled @p mass with its @p constraints, which
    /// @p constraint_map holds as a matrix. Collective.
    InterleavedMass(const dealii::PETScWrappers::MPI::SparseMatrix &mass,
                    const dealii::AffineConstraints<double>        &constraints,
                    const ConstraintMap &constraint_map);

    ~InterleavedMass();

    InterleavedMass(const InterleavedMass &) = delete;
    InterleavedMass &
    operator=(const InterleavedMass &) = delete;

    /// Whether the product uses the scalar matrix (else M's own).
    bool
    scalar() const;

    /// @p y = M @p x, for @p x zero on the constrained DoFs; @p y is zero
    /// there.
    void
    vmult(dealii::PETScWrappers::MPI::Vector       &y,
          const dealii::PETScWrappers::MPI::Vector &x) const;

  private:
    /// A row of m: (column, value), sorted by column.
    using ScalarRow  = std::vector<std::pair<PetscInt, PetscScalar>>;
    using ScalarRows = std::vector<ScalarRow>;

    /// This rank's rows of m from M's, if M = m ⊗ I2 on its unconstrained
    /// DoFs: whether it is.
    bool
    scalar_rows(const dealii::AffineConstraints<double> &constraints,
                ScalarRows                              &rows) const;

    /// The row of m from the x row's and the y row's entries: false if
    /// they differ at a common column by more than rounding.
    static bool
    merge(const ScalarRow &x_row, const ScalarRow &y_row, ScalarRow &row);

    /// m from this rank's @p rows and its product with both components.
    /// Collective.
    void
    create_scalar_matrix(const ScalarRows &rows);

    const dealii::PETScWrappers::MPI::SparseMatrix &mass;
    Mat                                             scalar_mass     = nullptr;
    Mat                                             both_components = nullptr;
    /// Zeroes the product's constrained entries.
    const ConstraintMap &constraint_map;
  };
} // namespace DiskImpact
