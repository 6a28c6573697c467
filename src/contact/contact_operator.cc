#include "contact/contact_operator.h"

#include "base/petsc_check.h"
#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace DiskImpact
{
  using namespace dealii;

  double
  ContactState::half_width() const
  {
    return force > 0. ? 2. * std::sqrt(second_moment / force) : 0.;
  }

  namespace
  {
    /// The largest |entry| of a ghosted vector's locally owned and ghost
    /// entries, on this rank alone (no communication).
    double
    local_max_abs(const PETScWrappers::MPI::Vector &ghosted)
    {
      Vec local;
      check_petsc(VecGhostGetLocalForm(ghosted, &local),
                  "VecGhostGetLocalForm");
      AssertThrow(local != nullptr, ExcMessage("expected a ghosted vector"));
      PetscInt           n;
      const PetscScalar *values;
      check_petsc(VecGetLocalSize(local, &n), "VecGetLocalSize");
      check_petsc(VecGetArrayRead(local, &values), "VecGetArrayRead");
      double largest = 0.;
      for (PetscInt i = 0; i < n; ++i)
        largest = std::max(largest, std::abs(values[i]));
      check_petsc(VecRestoreArrayRead(local, &values), "VecRestoreArrayRead");
      check_petsc(VecGhostRestoreLocalForm(ghosted, &local),
                  "VecGhostRestoreLocalForm");
      return largest;
    }
  } // namespace

  ContactOperator::ContactOperator(const ElasticityOperator &op,
                                   const RigidWall          &wall,
                                   const WallLaw            &law,
                                   const Point<2>           &disk_center)
      : op(op)
      , wall(wall)
      , law(law)
      , origin(disk_center - wall.gap(disk_center) * wall.normal)
      , tangent_direction({-wall.normal[1], wall.normal[0]})
  {
    // Each edge face's smallest undeformed gap, over its quadrature points.
    const auto     &fe = op.get_dof_handler().get_fe();
    FEFaceValues<2> face_values(op.get_mapping(),
                                fe,
                                QGauss<1>(fe.degree + 3),
                                update_quadrature_points);
    for_each_curved_edge_face(op.get_dof_handler(),
                              [&](const auto &cell, const unsigned int f) {
                                face_values.reinit(cell, f);
                                double gap = std::numeric_limits<double>::max();
                                for (const auto &x :
                                     face_values.get_quadrature_points())
                                  gap = std::min(gap, wall.gap(x));
                                face_gap.push_back(gap);
                              });
  }

  ContactState
  ContactOperator::assemble(const PETScWrappers::MPI::Vector &ghosted_u,
                            PETScWrappers::MPI::Vector       *residual,
                            PETScWrappers::MPI::SparseMatrix *tangent) const
  {
    const auto &dof_handler = op.get_dof_handler();
    const auto &fe          = dof_handler.get_fe();
    // More points than the element needs: the pressure has a kink where
    // contact ends inside a face.
    const QGauss<1>    quadrature(fe.degree + 3);
    FEFaceValues<2>    face_values(op.get_mapping(),
                                fe,
                                quadrature,
                                update_values | update_quadrature_points |
                                  update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>     cell_residual(dofs_per_cell);
    FullMatrix<double> cell_tangent(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::vector<Tensor<1, 2>>            u(quadrature.size());
    std::vector<double>                  phi_n(dofs_per_cell);
    const FEValuesExtractors::Vector     displacement(0);

    ContactState state;
    for_each_curved_edge_face(
      dof_handler, [&](const auto &cell, const unsigned int f) {
        face_values.reinit(cell, f);
        face_values[displacement].get_function_values(ghosted_u, u);
        bool in_contact = false;
        cell_residual   = 0.;
        cell_tangent    = 0.;
        for (const unsigned int q : face_values.quadrature_point_indices())
          {
            const Point<2> x   = face_values.quadrature_point(q) + u[q];
            const double   gap = wall.gap(x);
            if (gap >= 0.)
              continue;
            in_contact      = true;
            const double p  = law.pressure(gap);
            const double ds = face_values.JxW(q);
            // Hertz's coordinate: along the undeformed edge (the
            // deformed edge is shorter by a strain of order a / R).
            const double t =
              (face_values.quadrature_point(q) - origin) * tangent_direction;
            state.force += p * ds;
            state.energy += law.energy(gap) * ds;
            state.second_moment += p * t * t * ds;
            state.max_penetration = std::max(state.max_penetration, -gap);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              phi_n[i] = face_values[displacement].value(i, q) * wall.normal;
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                cell_residual(i) -= p * phi_n[i] * ds;
                for (unsigned int j = 0; j < dofs_per_cell; ++j)
                  cell_tangent(i, j) -=
                    law.pressure_derivative(gap) * phi_n[i] * phi_n[j] * ds;
              }
          }
        if (!in_contact)
          return;
        cell->get_dof_indices(dof_indices);
        if (residual != nullptr)
          op.get_constraints().distribute_local_to_global(cell_residual,
                                                          dof_indices,
                                                          *residual);
        if (tangent != nullptr)
          op.get_constraints().distribute_local_to_global(cell_tangent,
                                                          dof_indices,
                                                          *tangent);
      });

    const MPI_Comm comm   = dof_handler.get_communicator();
    state.force           = Utilities::MPI::sum(state.force, comm);
    state.energy          = Utilities::MPI::sum(state.energy, comm);
    state.second_moment   = Utilities::MPI::sum(state.second_moment, comm);
    state.max_penetration = Utilities::MPI::max(state.max_penetration, comm);
    return state;
  }

  ContactState
  ContactOperator::assemble_step(
    const PETScWrappers::MPI::Vector &ghosted_u_old,
    const PETScWrappers::MPI::Vector &ghosted_u_new,
    const ContactAverage              average,
    const double                      new_weight,
    PETScWrappers::MPI::Vector       &residual,
    std::vector<RankOneTerm>         *tangent_terms) const
  {
    const auto                          &dof_handler = op.get_dof_handler();
    const auto                          &fe          = dof_handler.get_fe();
    const auto                          &constraints = op.get_constraints();
    const QGauss<1>                      quadrature(fe.degree + 3);
    FEFaceValues<2>                      face_values(op.get_mapping(),
                                fe,
                                quadrature,
                                update_values | update_quadrature_points |
                                  update_JxW_values);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>                       cell_residual(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::vector<Tensor<1, 2>>            u_old(quadrature.size()),
      u_new(quadrature.size());
    std::vector<double>              phi_n(dofs_per_cell);
    const FEValuesExtractors::Vector displacement(0);
    if (tangent_terms != nullptr)
      tangent_terms->clear();
    // No point of a face whose undeformed gap exceeds the largest
    // displacement toward the wall can touch it: skip the face. |u . n| <=
    // max(|u_x|, |u_y|) (|n_x| + |n_y|), and between its nodes a Q_k field
    // exceeds its largest nodal value by at most the Lebesgue constant of
    // the face's 1D interpolation (below 2 up to k = 6). The bound is this
    // rank's own (its faces' DoFs are all in the ghosted vector): a norm of
    // the distributed vector would be collective, and PETSc may answer it
    // from a cache on some ranks only, which leaves the others waiting.
    const double reach =
      2. * (std::abs(wall.normal[0]) + std::abs(wall.normal[1])) *
      std::max(local_max_abs(ghosted_u_old), local_max_abs(ghosted_u_new));
    unsigned int face_index = 0;

    ContactState state;
    for_each_curved_edge_face(
      dof_handler, [&](const auto &cell, const unsigned int f) {
        if (face_gap[face_index++] > reach)
          return;
        face_values.reinit(cell, f);
        face_values[displacement].get_function_values(ghosted_u_old, u_old);
        face_values[displacement].get_function_values(ghosted_u_new, u_new);
        bool in_contact = false;
        cell_residual   = 0.;
        for (const unsigned int q : face_values.quadrature_point_indices())
          {
            const Point<2> &x  = face_values.quadrature_point(q);
            const double    g0 = wall.gap(x + u_old[q]);
            const double    g1 = wall.gap(x + u_new[q]);
            if (g0 >= 0. && g1 >= 0.)
              continue;
            in_contact      = true;
            const double ds = face_values.JxW(q);
            double       p_bar, dp_bar;
            if (average == ContactAverage::discrete_gradient)
              {
                p_bar  = law.discrete_gradient_pressure(g0, g1);
                dp_bar = law.discrete_gradient_derivative(g0, g1);
              }
            else
              {
                p_bar = (1. - new_weight) * law.pressure(g0) +
                        new_weight * law.pressure(g1);
                dp_bar = new_weight * law.pressure_derivative(g1);
              }
            const double t = (x - origin) * tangent_direction;
            state.force += law.pressure(g1) * ds;
            state.force_average += p_bar * ds;
            state.energy += law.energy(g1) * ds;
            state.second_moment += law.pressure(g1) * t * t * ds;
            state.max_penetration = std::max(state.max_penetration, -g1);

            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                phi_n[i] = face_values[displacement].value(i, q) * wall.normal;
                cell_residual(i) -= p_bar * phi_n[i] * ds;
              }
            if (tangent_terms == nullptr || dp_bar == 0.)
              continue;
            // -d p_bar / d g1 (n.phi_i)(n.phi_j) ds, constraints
            // resolved onto the unconstrained DoFs.
            cell->get_dof_indices(dof_indices);
            RankOneTerm term;
            term.weight = -dp_bar * ds;
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                if (phi_n[i] == 0.)
                  continue;
                const auto *entries =
                  constraints.get_constraint_entries(dof_indices[i]);
                if (entries == nullptr)
                  term.entries.emplace_back(dof_indices[i], phi_n[i]);
                else
                  for (const auto &[j, weight] : *entries)
                    term.entries.emplace_back(j, weight * phi_n[i]);
              }
            tangent_terms->push_back(std::move(term));
          }
        if (!in_contact)
          return;
        cell->get_dof_indices(dof_indices);
        constraints.distribute_local_to_global(cell_residual,
                                               dof_indices,
                                               residual);
      });

    const MPI_Comm comm   = dof_handler.get_communicator();
    state.force           = Utilities::MPI::sum(state.force, comm);
    state.force_average   = Utilities::MPI::sum(state.force_average, comm);
    state.energy          = Utilities::MPI::sum(state.energy, comm);
    state.second_moment   = Utilities::MPI::sum(state.second_moment, comm);
    state.max_penetration = Utilities::MPI::max(state.max_penetration, comm);
    return state;
  }

  std::vector<std::pair<double, double>>
  ContactOperator::pressure_profile(
    const PETScWrappers::MPI::Vector &ghosted_u) const
  {
    const auto               &dof_handler = op.get_dof_handler();
    const QGauss<1>           quadrature(dof_handler.get_fe().degree + 3);
    FEFaceValues<2>           face_values(op.get_mapping(),
                                dof_handler.get_fe(),
                                quadrature,
                                update_values | update_quadrature_points);
    std::vector<Tensor<1, 2>> u(quadrature.size());
    std::vector<std::pair<double, double>> samples;
    for_each_curved_edge_face(
      dof_handler, [&](const auto &cell, const unsigned int f) {
        face_values.reinit(cell, f);
        face_values[FEValuesExtractors::Vector(0)].get_function_values(
          ghosted_u, u);
        for (const unsigned int q : face_values.quadrature_point_indices())
          {
            const Point<2> x = face_values.quadrature_point(q) + u[q];
            const double   p = law.pressure(wall.gap(x));
            if (p > 0.)
              samples.emplace_back((face_values.quadrature_point(q) - origin) *
                                     tangent_direction,
                                   p);
          }
      });
    std::vector<std::pair<double, double>> all;
    for (const auto &part :
         Utilities::MPI::all_gather(dof_handler.get_communicator(), samples))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    return all;
  }

  double
  ContactOperator::smallest_edge_face(const ElasticityOperator &op)
  {
    double smallest = std::numeric_limits<double>::max();
    for_each_curved_edge_face(op.get_dof_handler(),
                              [&](const auto &cell, const unsigned int f) {
                                smallest =
                                  std::min(smallest, cell->face(f)->measure());
                              });
    return Utilities::MPI::min(smallest,
                               op.get_dof_handler().get_communicator());
  }
} // namespace DiskImpact
