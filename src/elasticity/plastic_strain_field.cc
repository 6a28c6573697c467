#include "elasticity/plastic_strain_field.h"

#include "material/plane_stress_return_mapping.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// sigma : eps(v) for a test function with in-plane strain @p eps and
    /// out-of-plane strain @p eps_zz.
    double
    stress_work(const SymmetricTensor<2, 3> &sigma,
                const SymmetricTensor<2, 2> &eps,
                const double                 eps_zz)
    {
      return sigma[0][0] * eps[0][0] + sigma[1][1] * eps[1][1] +
             2. * sigma[0][1] * eps[0][1] + sigma[2][2] * eps_zz;
    }

    double
    stress_work(const SymmetricTensor<2, 3> &sigma,
                const SymmetricTensor<2, 3> &eps,
                double)
    {
      return sigma * eps;
    }

    /// cell_tangent(i, j) += eps_i : (C_ep - C) : eps_j dV at point @p q,
    /// eps_i the three-dimensional strain of test function i.
    template <int dim>
    void
    add_tangent_correction(const SymmetricTensor<4, 3>        &correction,
                           const FEValues<dim>                &fe_values,
                           const Section<dim>                 &section,
                           const unsigned int                  q,
                           const double                        volume,
                           std::vector<SymmetricTensor<2, 3>> &test_strains,
                           FullMatrix<double>                 &cell_tangent)
    {
      const FEValuesExtractors::Vector displacement(0);
      const auto                      &x = fe_values.quadrature_point(q);
      for (unsigned int i = 0; i < test_strains.size(); ++i)
        test_strains[i] = three_dimensional(
          fe_values[displacement].symmetric_gradient(i, q),
          section.hoop_strain(fe_values[displacement].value(i, q), x));
      for (unsigned int i = 0; i < test_strains.size(); ++i)
        {
          const SymmetricTensor<2, 3> row = test_strains[i] * correction;
          for (unsigned int j = 0; j < test_strains.size(); ++j)
            cell_tangent(i, j) += (row * test_strains[j]) * volume;
        }
    }
  } // namespace

  template <int dim>
  PlasticStrainField<dim>::PlasticStrainField(
    const ElasticityOperator<dim> &op,
    const std::vector<Material>   &materials)
      : op(op)
  {
    for (const Material &material : materials)
      {
        if (!material.is_plastic())
          {
            return_mappings.emplace_back();
            continue;
          }
        if (dim == 2 && material.plane_model() == PlaneModel::plane_stress)
          return_mappings.push_back(std::make_unique<PlaneStressReturnMapping>(
            material.lame_lambda_3d(),
            material.shear_modulus_3d(),
            material.yield_stress(),
            material.hardening_modulus()));
        else
          return_mappings.push_back(
            std::make_unique<J2ReturnMapping>(material.lame_lambda_3d(),
                                              material.shear_modulus_3d(),
                                              material.yield_stress(),
                                              material.hardening_modulus()));
      }
    strain_energy_terms.assign(return_mappings.size(), 0.);
    const unsigned int n_points =
      Utilities::pow(op.get_dof_handler().get_fe().degree + 1, dim);
    const auto &triangulation = op.get_dof_handler().get_triangulation();
    points.resize(triangulation.n_active_cells());
    near_yield.resize(triangulation.n_active_cells(), true);
    for (const auto &cell : op.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        points[cell->active_cell_index()].resize(n_points);
  }

  template <int dim>
  void
  PlasticStrainField<dim>::evaluate(const PETScWrappers::MPI::Vector &u,
                                    PETScWrappers::MPI::Vector       &force,
                                    const bool                        all_cells,
                                    PETScWrappers::MPI::SparseMatrix *tangent)
  {
    const auto                          &dof_handler = op.get_dof_handler();
    const auto                          &fe          = dof_handler.get_fe();
    const auto                          &section     = op.get_section();
    const QGauss<dim>                    quadrature(fe.degree + 1);
    FEValues<dim>                        fe_values(op.get_mapping(),
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const auto                           ghosted       = op.create_ghosted(u);
    const unsigned int                   n_q           = quadrature.size();
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strains(n_q);
    std::vector<Tensor<1, dim>>          values(n_q);
    Vector<double>                       cell_force(dofs_per_cell);
    FullMatrix<double> cell_tangent(dofs_per_cell, dofs_per_cell);
    std::vector<SymmetricTensor<2, 3>>   test_strains(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    const bool                           single = return_mappings.size() == 1;

    force    = 0.;
    yielding = 0;
    unsigned int changed = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int which = single ? 0 : cell->material_id();
          AssertIndexRange(which, return_mappings.size());
          const unsigned int index = cell->active_cell_index();
          if (!return_mappings[which] || !(all_cells || near_yield[index]))
            continue;
          const J2ReturnMapping &return_mapping = *return_mappings[which];
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(ghosted,
                                                                   strains);
          fe_values[displacement].get_function_values(ghosted, values);
          auto &cell_points = points[index];
          cell_force        = 0.;
          cell_tangent      = 0.;
          bool plastic = false, yielded = false;
          if (all_cells)
            near_yield[index] = false;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              Point      &point  = cell_points[q];
              const auto &x      = fe_values.quadrature_point(q);
              const auto  update = return_mapping.update(
                three_dimensional(strains[q],
                                  section.hoop_strain(values[q], x)),
                point.accepted,
                tangent != nullptr);
              point.trial        = update.state;
              point.trial_stress = update.stress;
              point.volume       = fe_values.JxW(q) * section.measure(x);
              yielding += update.yielded;
              if (tangent != nullptr)
                point.in_tangent = update.yielded;
              else
                changed += update.yielded != point.in_tangent;
              if (tangent != nullptr && update.yielded)
                {
                  yielded = true;
                  add_tangent_correction(update.tangent -
                                           return_mapping.elastic_tangent(),
                                         fe_values,
                                         section,
                                         q,
                                         point.volume,
                                         test_strains,
                                         cell_tangent);
                }
              if (all_cells &&
                  std::sqrt(1.5) * deviator(update.stress).norm() >=
                    0.8 * (return_mapping.yield_stress() +
                           return_mapping.hardening_modulus() *
                             point.trial.equivalent_plastic_strain))
                near_yield[index] = true;
              if (point.trial.equivalent_plastic_strain == 0.)
                continue;
              // f_p: eps(v_i) : C : eps_p over the point's volume.
              plastic = true;
              if (all_cells)
                near_yield[index] = true;
              const SymmetricTensor<2, 3> plastic_stress =
                return_mapping.elastic_stress(point.trial.plastic_strain);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                cell_force[i] +=
                  stress_work(plastic_stress,
                              fe_values[displacement].symmetric_gradient(i, q),
                              section.hoop_strain(
                                fe_values[displacement].value(i, q), x)) *
                  point.volume;
            }
          if (!plastic)
            continue;
          cell->get_dof_indices(dof_indices);
          if (yielded)
            op.get_constraints().distribute_local_to_global(
              cell_tangent, cell_force, dof_indices, *tangent, force);
          else
            op.get_constraints().distribute_local_to_global(cell_force,
                                                            dof_indices,
                                                            force);
        }
    force.compress(VectorOperation::add);
    if (tangent != nullptr)
      tangent->compress(VectorOperation::add);
    yielding = Utilities::MPI::sum(yielding, dof_handler.get_communicator());
    if (tangent == nullptr)
      changed_since_tangent =
        Utilities::MPI::sum(changed, dof_handler.get_communicator());
    else
      changed_since_tangent = 0;
  }

  template <int dim>
  double
  PlasticStrainField<dim>::accept()
  {
    double              work = 0.;
    std::vector<double> energy(return_mappings.size(), 0.);
    for (const auto &cell : op.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int which =
            return_mappings.size() == 1 ? 0 : cell->material_id();
          if (!return_mappings[which])
            continue;
          for (auto &point : points[cell->active_cell_index()])
            {
              // The step's plastic work by the trapezoidal rule in the
              // stress: what the midpoint rule's energy balance holds.
              work +=
                (point.trial.plastic_strain - point.accepted.plastic_strain) *
                (0.5 * (point.stress + point.trial_stress)) * point.volume;
              point.accepted = point.trial;
              point.stress   = point.trial_stress;
              if (point.accepted.equivalent_plastic_strain > 0.)
                energy[which] += 0.5 *
                                 (point.accepted.plastic_strain *
                                  return_mappings[which]->elastic_stress(
                                    point.accepted.plastic_strain)) *
                                 point.volume;
            }
        }
    const MPI_Comm communicator = op.get_dof_handler().get_communicator();
    strain_energy_terms.resize(energy.size());
    Utilities::MPI::sum(ArrayView<const double>(energy),
                        communicator,
                        ArrayView<double>(strain_energy_terms));
    return Utilities::MPI::sum(work, communicator);
  }

  template <int dim>
  double
  PlasticStrainField<dim>::plastic_strain_energy() const
  {
    return std::accumulate(strain_energy_terms.begin(),
                           strain_energy_terms.end(),
                           0.);
  }

  template <int dim>
  double
  PlasticStrainField<dim>::plastic_strain_energy(const unsigned int body) const
  {
    if (strain_energy_terms.size() == 1)
      return body == 0 ? strain_energy_terms[0] : 0.;
    AssertIndexRange(body, strain_energy_terms.size());
    return strain_energy_terms[body];
  }

  template <int dim>
  double
  PlasticStrainField<dim>::largest_equivalent_plastic_strain() const
  {
    double largest = 0.;
    for (const auto &cell : op.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : points[cell->active_cell_index()])
          largest = std::max(largest, point.accepted.equivalent_plastic_strain);
    return Utilities::MPI::max(largest,
                               op.get_dof_handler().get_communicator());
  }

  template <int dim>
  unsigned int
  PlasticStrainField<dim>::n_yielding_points() const
  {
    return yielding;
  }

  template <int dim>
  unsigned int
  PlasticStrainField<dim>::n_changed_since_tangent() const
  {
    return changed_since_tangent;
  }

  template <int dim>
  Vector<float>
  PlasticStrainField<dim>::largest_per_cell(
    const std::function<double(const Point &)> &value) const
  {
    const auto   &triangulation = op.get_dof_handler().get_triangulation();
    Vector<float> largest(triangulation.n_active_cells());
    for (const auto &cell : op.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : points[cell->active_cell_index()])
          largest[cell->active_cell_index()] =
            std::max<float>(largest[cell->active_cell_index()], value(point));
    return largest;
  }

  template <int dim>
  Vector<float>
  PlasticStrainField<dim>::equivalent_plastic_strain_per_cell() const
  {
    return largest_per_cell([](const Point &point) {
      return point.accepted.equivalent_plastic_strain;
    });
  }

  template <int dim>
  Vector<float>
  PlasticStrainField<dim>::von_mises_stress_per_cell() const
  {
    return largest_per_cell([](const Point &point) {
      return std::sqrt(1.5) * deviator(point.stress).norm();
    });
  }

  template class PlasticStrainField<2>;
  template class PlasticStrainField<3>;
} // namespace DiskImpact
