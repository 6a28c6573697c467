#include "elasticity/body_motion.h"

#include "elasticity/elasticity_operator.h"

#include <deal.II/fe/fe.h>

namespace DiskImpact
{
  using namespace dealii;

  template <int dim>
  BodyMotion<dim>::BodyMotion(const ElasticityOperator<dim> &op,
                              const Tensor<1, dim>          &normal,
                              const unsigned int             n_bodies)
      : op(op)
      , work(op.create_vector())
      , product(op.create_vector())
  {
    const auto                          &dof_handler = op.get_dof_handler();
    const auto                          &fe          = dof_handler.get_fe();
    const auto                          &owned       = op.locally_owned_dofs();
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (unsigned int body = 0; body < n_bodies; ++body)
      {
        auto n_i = op.create_vector(), chi_i = op.create_vector();
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == body)
            {
              cell->get_dof_indices(dof_indices);
              for (unsigned int k = 0; k < dof_indices.size(); ++k)
                if (owned.is_element(dof_indices[k]))
                  {
                    const unsigned int component =
                      fe.system_to_component_index(k).first;
                    n_i(dof_indices[k])   = normal[component];
                    chi_i(dof_indices[k]) = 1.;
                  }
            }
        n_i.compress(VectorOperation::insert);
        chi_i.compress(VectorOperation::insert);
        // Uniform on the body, constraints included (a uniform field
        // satisfies the hanging-node constraints; the symmetry line's u_y = 0
        // holds for n along x).
        op.get_constraints().distribute(n_i);
        auto momentum = op.mass_functional(n_i);
        masses.push_back(momentum * n_i);
        normals.push_back(std::move(n_i));
        indicators.push_back(std::move(chi_i));
        momenta.push_back(std::move(momentum));
      }
  }

  template <int dim>
  unsigned int
  BodyMotion<dim>::n_bodies() const
  {
    return normals.size();
  }

  template <int dim>
  const PETScWrappers::MPI::Vector &
  BodyMotion<dim>::normal_field(const unsigned int body) const
  {
    return normals[body];
  }

  template <int dim>
  double
  BodyMotion<dim>::mass(const unsigned int body) const
  {
    return masses[body];
  }

  template <int dim>
  double
  BodyMotion<dim>::center_of_mass(const unsigned int                body,
                                  const PETScWrappers::MPI::Vector &x) const
  {
    return (momenta[body] * x) / masses[body];
  }

  template <int dim>
  double
  BodyMotion<dim>::quadratic_form(
    const unsigned int                      body,
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const PETScWrappers::MPI::Vector       &x) const
  {
    work = x;
    work.scale(indicators[body]);
    op.get_constraints().set_zero(work);
    matrix.vmult(product, work);
    return 0.5 * (work * product);
  }

  template <int dim>
  double
  BodyMotion<dim>::dot(const unsigned int                body,
                       const PETScWrappers::MPI::Vector &x,
                       const PETScWrappers::MPI::Vector &y) const
  {
    work = x;
    work.scale(indicators[body]);
    op.get_constraints().set_zero(work);
    return work * y;
  }

  template class BodyMotion<2>;
  template class BodyMotion<3>;
} // namespace DiskImpact
