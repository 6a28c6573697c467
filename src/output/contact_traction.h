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
   * displacement's finite element, for ParaView: nodal contact forces
   * divided by each DoF's surface weight, the integral of its shape
   * function over the curved edge (times the section's measure), which is
   * assembled once, at construction (collective). A uniform traction is
   * returned exactly; the normal and tangential components are its
   * projections on the wall's normal and tangents.
   */
  template <int dim>
  class ContactTraction
  {
  public:
    explicit ContactTraction(const ElasticityOperator<dim> &op);

    /// The traction of the nodal forces @p forces on the DoFs @p dofs
    /// (every rank holds them all): zero away from the contact, hanging
    /// nodes following the constraints. Returns a ghosted vector.
    /// Collective.
    dealii::PETScWrappers::MPI::Vector
    operator()(const std::vector<dealii::types::global_dof_index> &dofs,
               const dealii::Vector<double> &forces) const;

  private:
    const ElasticityOperator<dim>     &op;
    dealii::PETScWrappers::MPI::Vector weights;
  };
} // namespace DiskImpact
