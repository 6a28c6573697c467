#include "elasticity/interleaved_mass.h"

#include "base/petsc_check.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace DiskImpact
{
  using namespace dealii;

  InterleavedMass::InterleavedMass(const PETScWrappers::MPI::SparseMatrix &mass,
                                   const AffineConstraints<double> &constraints,
                                   const ConstraintMap &constraint_map)
      : mass(mass)
      , constraint_map(constraint_map)
  {
    ScalarRows rows;
    const bool whole = scalar_rows(constraints, rows);
    // All ranks take the same product (creating m and the product are
    // collective).
    if (Utilities::MPI::min(whole ? 1 : 0, mass.get_mpi_communicator()) == 1)
      create_scalar_matrix(rows);
  }

  InterleavedMass::~InterleavedMass()
  {
    if (both_components != nullptr)
      MatDestroy(&both_components);
    if (scalar_mass != nullptr)
      MatDestroy(&scalar_mass);
  }

  bool
  InterleavedMass::scalar_rows(const AffineConstraints<double> &constraints,
                               ScalarRows                      &rows) const
  {
    PetscInt start, end, n;
    check_petsc(MatGetOwnershipRange(mass, &start, &end),
                "MatGetOwnershipRange");
    check_petsc(MatGetSize(mass, &n, nullptr), "MatGetSize");
    if (start % 2 != 0 || end % 2 != 0 || n % 2 != 0)
      return false;
    // Row p of m: the x row's entries at unconstrained x columns and the y
    // row's at unconstrained y columns, which must agree where both exist
    // (to rounding: the assembled entries are an ulp apart in places).
    // Both rows' columns are sorted, so their scalar columns are too.
    rows.resize((end - start) / 2);
    std::array<ScalarRow, 2> component_row;
    for (PetscInt p = start / 2; p < end / 2; ++p)
      {
        for (unsigned int component = 0; component < 2; ++component)
          {
            const PetscInt row             = 2 * p + component;
            const bool     row_constrained = constraints.is_constrained(row);
            auto          &entries         = component_row[component];
            entries.clear();
            PetscInt           n_entries;
            const PetscInt    *columns;
            const PetscScalar *values;
            check_petsc(MatGetRow(mass, row, &n_entries, &columns, &values),
                        "MatGetRow");
            bool coupled = false;
            for (PetscInt k = 0; k < n_entries; ++k)
              {
                // An entry that couples x with y (a constrained row's own
                // diagonal aside) breaks the structure.
                coupled = coupled || columns[k] % 2 != PetscInt(component);
                if (!row_constrained && !constraints.is_constrained(columns[k]))
                  entries.emplace_back(columns[k] / 2, values[k]);
              }
            check_petsc(MatRestoreRow(mass, row, &n_entries, &columns, &values),
                        "MatRestoreRow");
            if (coupled)
              return false;
          }
        if (!merge(component_row[0], component_row[1], rows[p - start / 2]))
          return false;
      }
    return true;
  }

  bool
  InterleavedMass::merge(const ScalarRow &x_row,
                         const ScalarRow &y_row,
                         ScalarRow       &row)
  {
    row.clear();
    row.reserve(std::max(x_row.size(), y_row.size()));
    auto x = x_row.begin(), y = y_row.begin();
    while (x != x_row.end() || y != y_row.end())
      if (y == y_row.end() || (x != x_row.end() && x->first < y->first))
        row.push_back(*x++);
      else if (x == x_row.end() || y->first < x->first)
        row.push_back(*y++);
      else
        {
          if (std::abs(x->second - y->second) > 1e-12 * std::abs(y->second))
            return false;
          row.push_back(*x++);
          ++y;
        }
    return true;
  }

  void
  InterleavedMass::create_scalar_matrix(const ScalarRows &rows)
  {
    PetscInt start, end, n;
    check_petsc(MatGetOwnershipRange(mass, &start, &end),
                "MatGetOwnershipRange");
    check_petsc(MatGetSize(mass, &n, nullptr), "MatGetSize");
    const PetscInt        first = start / 2, last = end / 2;
    std::vector<PetscInt> diagonal_counts(rows.size()),
      off_diagonal_counts(rows.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (const auto &entry : rows[r])
        ++(entry.first >= first && entry.first < last ? diagonal_counts[r] :
                                                        off_diagonal_counts[r]);
    check_petsc(MatCreateAIJ(mass.get_mpi_communicator(),
                             last - first,
                             last - first,
                             n / 2,
                             n / 2,
                             0,
                             diagonal_counts.data(),
                             0,
                             off_diagonal_counts.data(),
                             &scalar_mass),
                "MatCreateAIJ");
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        const PetscInt           row = first + r;
        std::vector<PetscInt>    columns;
        std::vector<PetscScalar> values;
        for (const auto &[column, value] : rows[r])
          {
            columns.push_back(column);
            values.push_back(value);
          }
        check_petsc(MatSetValues(scalar_mass,
                                 1,
                                 &row,
                                 columns.size(),
                                 columns.data(),
                                 values.data(),
                                 INSERT_VALUES),
                    "MatSetValues");
      }
    check_petsc(MatAssemblyBegin(scalar_mass, MAT_FINAL_ASSEMBLY),
                "MatAssemblyBegin");
    check_petsc(MatAssemblyEnd(scalar_mass, MAT_FINAL_ASSEMBLY),
                "MatAssemblyEnd");
    check_petsc(MatCreateMAIJ(scalar_mass, 2, &both_components),
                "MatCreateMAIJ");
  }

  bool
  InterleavedMass::scalar() const
  {
    return both_components != nullptr;
  }

  void
  InterleavedMass::vmult(PETScWrappers::MPI::Vector       &y,
                         const PETScWrappers::MPI::Vector &x) const
  {
    if (!scalar())
      {
        mass.vmult(y, x);
        return;
      }
    check_petsc(MatMult(both_components, x, y), "MatMult");
    // M's constrained rows hold their diagonal alone, and x is zero there.
    constraint_map.set_zero(y);
  }
} // namespace DiskImpact
