#pragma once

// A function as a finite element field of the unit tests' operators.

#include "elasticity/elasticity_operator.h"

#include <deal.II/base/function.h>

#include <deal.II/lac/petsc_vector.h>

#include <deal.II/numerics/vector_tools.h>

namespace DiskImpact
{
  /// @p f interpolated on @p op's DoFs, constraints applied.
  template <int dim>
  dealii::PETScWrappers::MPI::Vector
  interpolated_field(const ElasticityOperator<dim> &op,
                     const dealii::Function<dim>   &f)
  {
    auto u = op.create_vector();
    dealii::VectorTools::interpolate(op.get_mapping(),
                                     op.get_dof_handler(),
                                     f,
                                     u);
    op.get_constraints().distribute(u);
    return u;
  }
} // namespace DiskImpact
