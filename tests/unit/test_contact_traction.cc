// The contact traction field of the outputs: nodal forces of a uniform
// traction are turned back into that traction at every DoF of the curved
// edge.

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "half_disk.h"
#include "output/contact_traction.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/fe/fe_values.h>

#include <catch2/catch.hpp>

#include <map>

using namespace DiskImpact;

TEST_CASE("contact traction: a uniform traction is recovered exactly",
          "[traction][fe]")
{
  // Edge faces of three sizes (contact refinements).
  const BodyGeometry geometry = half_disk(2, 2);
  dealii::parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
  geometry.create_triangulation(triangulation);
  ElasticityOperator<2> op(2);
  op.setup(triangulation, geometry);

  // The nodal forces of the traction t on the whole curved edge.
  const dealii::Tensor<1, 2> t({0.3, -0.7});
  const auto                &dof_handler = op.get_dof_handler();
  const auto                &fe          = dof_handler.get_fe();
  dealii::FEFaceValues<2>    face_values(op.get_mapping(),
                                      fe,
                                      dealii::QGauss<1>(fe.degree + 1),
                                      dealii::update_values |
                                        dealii::update_quadrature_points |
                                        dealii::update_JxW_values);
  std::vector<dealii::types::global_dof_index> dof_indices(
    fe.n_dofs_per_cell());
  dealii::Vector<double> cell_force(fe.n_dofs_per_cell());
  auto                   force = op.create_vector();
  // Each edge DoF's component, to compare with.
  std::map<dealii::types::global_dof_index, unsigned int> edge_dofs;
  for_each_curved_edge_face(dof_handler, [&](const auto &cell, unsigned int f) {
    face_values.reinit(cell, f);
    cell->get_dof_indices(dof_indices);
    cell_force = 0.;
    for (const unsigned int q : face_values.quadrature_point_indices())
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          cell_force[i] += t[c] * face_values.shape_value(i, q) *
                           face_values.JxW(q) *
                           op.get_section().measure(
                             face_values.quadrature_point(q));
        }
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.has_support_on_face(i, f))
        edge_dofs[dof_indices[i]] = fe.system_to_component_index(i).first;
    op.get_constraints().distribute_local_to_global(cell_force,
                                                    dof_indices,
                                                    force);
  });
  force.compress(dealii::VectorOperation::add);

  // Every rank holds the DoFs that carry a force, and the forces.
  std::vector<dealii::types::global_dof_index> dofs;
  dealii::Vector<double>                       forces;
  {
    std::vector<std::pair<dealii::types::global_dof_index, double>> local;
    for (const auto i : force.locally_owned_elements())
      if (force[i] != 0.)
        local.emplace_back(i, force[i]);
    std::vector<std::pair<dealii::types::global_dof_index, double>> all;
    for (const auto &part :
         dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      all.insert(all.end(), part.begin(), part.end());
    forces.reinit(all.size());
    for (unsigned int k = 0; k < all.size(); ++k)
      {
        dofs.push_back(all[k].first);
        forces[k] = all[k].second;
      }
  }
  REQUIRE(dofs.size() > 20);

  const auto   traction    = ContactTraction<2>(op)(dofs, forces);
  const auto &constraints = op.get_constraints();
  unsigned int checked = 0;
  for (const auto &[dof, component] : edge_dofs)
    {
      // The symmetry axis' u_y = 0 stays 0; the other DoFs carry t.
      if (constraints.is_constrained(dof))
        continue;
      ++checked;
      CHECK(traction[dof] == Approx(t[component]).epsilon(1e-12));
    }
  CHECK(checked > 20);
}
