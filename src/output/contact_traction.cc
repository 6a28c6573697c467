#include "output/contact_traction.h"

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// Each DoF's integral of its shape function over the curved edge,
    /// times the section's measure (constraints distributed).
    template <int dim>
    PETScWrappers::MPI::Vector
    surface_weights(const ElasticityOperator<dim> &op)
    {
      const auto                          &dof_handler = op.get_dof_handler();
      const auto                          &fe          = dof_handler.get_fe();
      FEFaceValues<dim>                    face_values(op.get_mapping(),
                                    fe,
                                    QGauss<dim - 1>(fe.degree + 1),
                                    update_values | update_quadrature_points |
                                      update_JxW_values);
      Vector<double>                       cell_weights(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      auto                                 weights = op.create_vector();
      for_each_curved_edge_face(
        dof_handler, [&](const auto &cell, const unsigned int f) {
          face_values.reinit(cell, f);
          cell_weights = 0.;
          for (const unsigned int q : face_values.quadrature_point_indices())
            {
              const double ds =
                face_values.JxW(q) *
                op.get_section().measure(face_values.quadrature_point(q));
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                cell_weights[i] += face_values.shape_value(i, q) * ds;
            }
          cell->get_dof_indices(dof_indices);
          op.get_constraints().distribute_local_to_global(cell_weights,
                                                          dof_indices,
                                                          weights);
        });
      weights.compress(VectorOperation::add);
      return weights;
    }
  } // namespace

  template <int dim>
  ContactTraction<dim>::ContactTraction(const ElasticityOperator<dim> &op)
      : op(op)
      , weights(surface_weights(op))
  {
  }

  template <int dim>
  PETScWrappers::MPI::Vector
  ContactTraction<dim>::operator()(
    const std::vector<types::global_dof_index> &dofs,
    const Vector<double>                       &forces) const
  {
    auto        traction = op.create_vector();
    const auto &owned    = op.locally_owned_dofs();
    for (unsigned int k = 0; k < dofs.size(); ++k)
      if (owned.is_element(dofs[k]) && weights[dofs[k]] > 0.)
        traction[dofs[k]] = forces[k] / weights[dofs[k]];
    traction.compress(VectorOperation::insert);
    op.get_constraints().distribute(traction);
    return op.create_ghosted(traction);
  }

  template class ContactTraction<2>;
  template class ContactTraction<3>;
} // namespace DiskImpact
