#pragma once

#include <deal.II/base/types.h>

#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;

  /**
   * The contact's traction on the body's surface as a field of the
   * displacement's finite element, for ParaView: the nodal contact forces
   * @p forces on the DoFs @p dofs (every rank holds them all) divided by
   * each DoF's surface weight, the integral of its shape function over the
   * curved edge (times the section's measure). A uniform traction is
   * returned exactly; the normal and tangential components are its
   * projections on the wall's normal and tangents. Zero away from the
   * contact; hanging nodes follow the constraints. Returns a ghosted vector.
   * Collective.
   */
  template <int dim>
  dealii::PETScWrappers::MPI::Vector
  contact_traction(const ElasticityOperator<dim>                      &op,
                   const std::vector<dealii::types::global_dof_index> &dofs,
                   const dealii::Vector<double>                       &forces);
} // namespace DiskImpact
