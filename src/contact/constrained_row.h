#pragma once

#include <deal.II/base/types.h>

#include <deal.II/lac/affine_constraints.h>

#include <map>

namespace DiskImpact
{
  /// A linear functional of the DoFs, sum_j row[j] u_j, over the
  /// unconstrained DoFs only.
  using ConstrainedRow = std::map<dealii::types::global_dof_index, double>;

  /// Add @p value u_dof to @p row; a constrained DoF (hanging node) as its
  /// masters with their weights (the symmetry condition's u_y = 0 has
  /// none, so it drops out).
  inline void
  add_to_row(const dealii::AffineConstraints<double> &constraints,
             const dealii::types::global_dof_index    dof,
             const double                             value,
             ConstrainedRow                          &row)
  {
    if (value == 0.)
      return;
    const auto *entries = constraints.get_constraint_entries(dof);
    if (entries == nullptr)
      row[dof] += value;
    else
      for (const auto &[master, weight] : *entries)
        row[master] += weight * value;
  }
} // namespace DiskImpact
