#include "elasticity/torsion_operator.h"

#include "body/geometry.h"
#include "material/material.h"

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  using namespace dealii;

  TorsionOperator::TorsionOperator(const unsigned int degree)
      : DiscreteOperator<2>(degree)
      , fe(degree)
  {
  }

  void
  TorsionOperator::setup(
    const parallel::distributed::Triangulation<2> &triangulation,
    const BodyGeometry                            &geometry)
  {
    if (!geometry.is_axisymmetric())
      throw std::invalid_argument(
        "TorsionOperator: torsion needs an axisymmetric body");
    distribute_dofs(triangulation, fe);

    // On the axis the azimuthal displacement vanishes.
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(*mapping,
                                             dof_handler,
                                             BoundaryIds::symmetry,
                                             Functions::ZeroFunction<2>(),
                                             constraints);
    constraints.close();

    const MPI_Comm         comm = triangulation.get_communicator();
    DynamicSparsityPattern dsp(relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned_dofs,
                                               comm,
                                               relevant_dofs);
    stiffness.reinit(owned_dofs, owned_dofs, dsp, comm);
    mass.reinit(owned_dofs, owned_dofs, dsp, comm);
  }

  void
  TorsionOperator::assemble(const Material &material)
  {
    const QGauss<2>                      quadrature(fe_degree + 1);
    FEValues<2>                          fe_values(*mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients |
                            update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_mass(n, n), cell_stiffness(n, n);
    std::vector<types::global_dof_index> dof_indices(n);
    std::vector<double>                  shear_r(n), shear_z(n), value(n);
    const double mu = material.shear_modulus(), rho = material.density();

    mass      = 0.;
    stiffness = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_mass      = 0.;
          cell_stiffness = 0.;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              // r = y, z = x; Gauss points never lie on the axis.
              const double r  = fe_values.quadrature_point(q)[1];
              const double dV = 2. * M_PI * r * fe_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const Tensor<1, 2> grad = fe_values.shape_grad(i, q);
                  value[i]                = fe_values.shape_value(i, q);
                  shear_r[i]              = grad[1] - value[i] / r;
                  shear_z[i]              = grad[0];
                }
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    cell_stiffness(i, j) +=
                      mu * (shear_r[i] * shear_r[j] + shear_z[i] * shear_z[j]) *
                      dV;
                    cell_mass(i, j) += rho * value[i] * value[j] * dV;
                  }
            }
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(cell_mass, dof_indices, mass);
          constraints.distribute_local_to_global(cell_stiffness,
                                                 dof_indices,
                                                 stiffness);
        }
    mass.compress(VectorOperation::add);
    stiffness.compress(VectorOperation::add);
  }

} // namespace DiskImpact
