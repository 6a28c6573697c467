#include "contact/contact_operator.h"

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
    if (!(force > 0.))
      return 0.;
    // Strip: int p t^2 dt / int p dt = a^2 / 4; circle (dS = 2 pi t dt):
    // 2 a^2 / 5.
    return std::sqrt((axisymmetric ? 2.5 : 4.) * second_moment / force);
  }

  template <int dim>
  ContactOperator<dim>::ContactOperator(const ElasticityOperator<dim>    &op,
                                        const RigidWall<dim>             &wall,
                                        std::shared_ptr<const ContactLaw> law,
                                        const Point<dim> &body_center,
                                        const bool        circular)
      : op(op)
      , wall(wall)
      , law(std::move(law))
      , circular(circular)
      , origin(body_center - wall.gap(body_center) * wall.normal)
      , tangent_direction(wall.tangents()[0])
  {
  }

  template <int dim>
  double
  ContactOperator<dim>::coordinate_along_wall(const Point<dim> &x) const
  {
    // Hertz's coordinate: along the undeformed edge (the deformed edge is
    // shorter by a strain of order a / R).
    const Tensor<1, dim> offset = x - origin;
    if (circular)
      return (offset - (offset * wall.normal) * wall.normal).norm();
    return offset * tangent_direction;
  }

  template <int dim>
  ContactState
  ContactOperator<dim>::assemble(
    const PETScWrappers::MPI::Vector &ghosted_u,
    PETScWrappers::MPI::Vector       *residual,
    PETScWrappers::MPI::SparseMatrix *tangent) const
  {
    const auto &dof_handler = op.get_dof_handler();
    const auto &fe          = dof_handler.get_fe();
    // More points than the element needs: the pressure has a kink where
    // contact ends inside a face.
    const QGauss<dim - 1> quadrature(fe.degree + 3);
    FEFaceValues<dim>     face_values(op.get_mapping(),
                                  fe,
                                  quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
    const unsigned int    dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>        cell_residual(dofs_per_cell);
    FullMatrix<double>    cell_tangent(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::vector<Tensor<1, dim>>          u(quadrature.size());
    std::vector<double>                  phi_n(dofs_per_cell);
    const FEValuesExtractors::Vector     displacement(0);

    const Section<dim> &section = op.get_section();
    ContactState        state;
    state.axisymmetric = section.is_axisymmetric() || circular;
    for_each_curved_edge_face(
      dof_handler, [&](const auto &cell, const unsigned int f) {
        face_values.reinit(cell, f);
        face_values[displacement].get_function_values(ghosted_u, u);
        bool in_contact = false;
        cell_residual   = 0.;
        cell_tangent    = 0.;
        for (const unsigned int q : face_values.quadrature_point_indices())
          {
            const Point<dim> x   = face_values.quadrature_point(q) + u[q];
            const double     gap = wall.gap(x);
            if (gap >= 0.)
              continue;
            in_contact      = true;
            const double p  = law->pressure(gap);
            const double ds = face_values.JxW(q) *
                              section.measure(face_values.quadrature_point(q));
            const double t =
              coordinate_along_wall(face_values.quadrature_point(q));
            state.force += p * ds;
            state.energy += law->energy(gap) * ds;
            state.second_moment += p * t * t * ds;
            state.max_penetration = std::max(state.max_penetration, -gap);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              phi_n[i] = face_values[displacement].value(i, q) * wall.normal;
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                cell_residual(i) -= p * phi_n[i] * ds;
                for (unsigned int j = 0; j < dofs_per_cell; ++j)
                  cell_tangent(i, j) -=
                    law->pressure_derivative(gap) * phi_n[i] * phi_n[j] * ds;
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

  template <int dim>
  std::vector<std::pair<double, double>>
  ContactOperator<dim>::pressure_profile(
    const PETScWrappers::MPI::Vector &ghosted_u) const
  {
    const auto                 &dof_handler = op.get_dof_handler();
    const QGauss<dim - 1>       quadrature(dof_handler.get_fe().degree + 3);
    FEFaceValues<dim>           face_values(op.get_mapping(),
                                  dof_handler.get_fe(),
                                  quadrature,
                                  update_values | update_quadrature_points);
    std::vector<Tensor<1, dim>> u(quadrature.size());
    std::vector<std::pair<double, double>> samples;
    for_each_curved_edge_face(
      dof_handler, [&](const auto &cell, const unsigned int f) {
        face_values.reinit(cell, f);
        face_values[FEValuesExtractors::Vector(0)].get_function_values(
          ghosted_u, u);
        for (const unsigned int q : face_values.quadrature_point_indices())
          {
            const Point<dim> x = face_values.quadrature_point(q) + u[q];
            const double     p = law->pressure(wall.gap(x));
            if (p > 0.)
              samples.emplace_back(
                coordinate_along_wall(face_values.quadrature_point(q)), p);
          }
      });
    std::vector<std::pair<double, double>> all;
    for (const auto &part :
         Utilities::MPI::all_gather(dof_handler.get_communicator(), samples))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    return all;
  }

  template <int dim>
  double
  smallest_edge_face(const ElasticityOperator<dim> &op,
                     const bool                     extruded_along_z)
  {
    const auto size = [extruded_along_z](const auto &face) {
      const double measure = face->measure();
      if (dim == 2)
        return measure;
      if (!extruded_along_z)
        return std::sqrt(measure);
      double lowest = std::numeric_limits<double>::max(), highest = -lowest;
      for (const unsigned int v : face->vertex_indices())
        {
          lowest  = std::min(lowest, face->vertex(v)[dim - 1]);
          highest = std::max(highest, face->vertex(v)[dim - 1]);
        }
      return measure / (highest - lowest);
    };
    double smallest = std::numeric_limits<double>::max();
    for_each_curved_edge_face(op.get_dof_handler(),
                              [&](const auto &cell, const unsigned int f) {
                                smallest =
                                  std::min(smallest, size(cell->face(f)));
                              });
    return Utilities::MPI::min(smallest,
                               op.get_dof_handler().get_communicator());
  }

  template class ContactOperator<2>;
  template class ContactOperator<3>;
  template double
  smallest_edge_face(const ElasticityOperator<2> &, bool);
  template double
  smallest_edge_face(const ElasticityOperator<3> &, bool);
} // namespace DiskImpact
