#include "quasistatic/wall_contact_problem.h"

#include "base/run_error.h"
#include "dynamics/factorization.h"
#include "elasticity/largest_von_mises.h"
#include "output/state_output.h"
#include "quasistatic/quasistatic_contact.h"
#include "run/parameters.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/vector_tools.h>

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  Reference::FirstYield
  hertz_first_yield(const Parameters &parameters)
  {
    const Material &material = parameters.material;
    if (parameters.geometry.is_axisymmetric())
      return Reference::sphere_first_yield(material.poisson_ratio());
    return Reference::half_plane_first_yield(
      material.plane_model() == PlaneModel::plane_strain ?
        material.poisson_ratio() :
        0.);
  }

  template <int dim>
  WallContactProblem<dim>::WallContactProblem(const Parameters &parameters,
                                              const double      load,
                                              const double      mesh_load,
                                              MPI_Comm          communicator)
      : parameters(parameters)
      , load(load)
      , theory(Reference::wall_contact_theory(parameters.geometry.is_sphere()))
      , communicator(communicator)
      , triangulation(communicator,
                      Triangulation<dim>::limit_level_difference_at_vertices)
      , op(parameters.finite_element.degree)
      , wall(parameters.contact.wall<dim>())
      , hold_dof(numbers::invalid_dof_index)
  {
    const auto &geometry = parameters.geometry;
    parameters.task_parameters<QuasistaticContact>().create_mesh(parameters,
                                                                 mesh_load,
                                                                 triangulation);
    op.setup(triangulation, geometry, true);
    op.assemble(parameters.material);

    h_contact = smallest_edge_face(op, dim == 3 && !geometry.is_sphere());
    contact   = std::make_unique<ContactOperator<dim>>(
      op,
      wall,
      parameters.contact.law({parameters.material.in_plane_young_modulus(),
                                h_contact,
                                geometry.radius()}),
      embedded<dim>(geometry.center()),
      dim == 3 && geometry.is_sphere());

    body_force    = op.create_vector();
    plastic_force = op.create_vector();
    solution      = op.create_vector();
    set_load(mesh_load);
    force_scale = body_force.l2_norm();
    set_load(load);

    // The wall-normal DoF at the point nearest the wall (in 3D on the
    // plane z = 0).
    const Point<dim> pole =
      embedded<dim>(geometry.center()) - geometry.radius() * wall.normal;
    const unsigned int component = std::abs(wall.normal[0]) > 0.5 ? 0 : 1;
    for (const auto &cell : op.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).distance(pole) < 1e-10 * geometry.radius())
            hold_dof = cell->vertex_dof_index(v, component);
    owns_hold = hold_dof != numbers::invalid_dof_index &&
                op.get_dof_handler().locally_owned_dofs().is_element(hold_dof);
  }

  template <int dim>
  WallContactProblem<dim>::~WallContactProblem() = default;

  template <int dim>
  void
  WallContactProblem<dim>::enable_plasticity()
  {
    plasticity = std::make_unique<PlasticStrainField<dim>>(
      op, std::vector<Material>{parameters.material});
  }

  template <int dim>
  void
  WallContactProblem<dim>::set_load(const double new_load)
  {
    // Uniform body force toward the wall, P in total on the whole body:
    // P / 2 on the half disk, P on a sphere's meridian (whose integrals
    // are over the sphere), P H / 4 on the quarter of a disk of thickness
    // H, divided by the discrete area or volume so that the force applied
    // is exactly that.
    load       = new_load;
    body_force = 0.;
    op.assemble_body_force(-parameters.geometry.domain_share() * force(load) /
                             op.volume() * wall.normal,
                           body_force);
  }

  template <int dim>
  double
  WallContactProblem<dim>::get_load() const
  {
    return load;
  }

  template <int dim>
  double
  WallContactProblem<dim>::force(const double any_load) const
  {
    return any_load *
           theory->force_unit(parameters.material.in_plane_young_modulus(),
                              parameters.geometry.radius());
  }

  template <int dim>
  unsigned int
  WallContactProblem<dim>::n_dofs() const
  {
    return op.get_dof_handler().n_dofs();
  }

  template <int dim>
  double
  WallContactProblem<dim>::domain_share() const
  {
    return parameters.geometry.domain_share();
  }

  template <int dim>
  void
  WallContactProblem<dim>::translate(const double compression)
  {
    const Tensor<1, dim> shift =
      -compression * parameters.geometry.radius() * wall.normal;
    std::vector<double> values(dim);
    for (unsigned int d = 0; d < dim; ++d)
      values[d] = shift[d];
    VectorTools::interpolate(op.get_mapping(),
                             op.get_dof_handler(),
                             Functions::ConstantFunction<dim>(values),
                             solution);
    op.get_constraints().distribute(solution);
  }

  template <int dim>
  ContactState
  WallContactProblem<dim>::add_support(
    const PETScWrappers::MPI::Vector &u,
    PETScWrappers::MPI::Vector       &r,
    PETScWrappers::MPI::SparseMatrix *tangent) const
  {
    ContactState state;
    if (load > 0.)
      state = contact->assemble(op.create_ghosted(u), &r, tangent);
    else if (owns_hold)
      {
        const double k = op.stiffness_matrix().diag_element(hold_dof);
        r(hold_dof) += k * u(hold_dof);
        if (tangent != nullptr)
          tangent->add(hold_dof, hold_dof, k);
      }
    r.compress(VectorOperation::add);
    if (tangent != nullptr)
      tangent->compress(VectorOperation::add);
    return state;
  }

  template <int dim>
  ContactState
  WallContactProblem<dim>::residual(const PETScWrappers::MPI::Vector &u,
                                    PETScWrappers::MPI::Vector       &r,
                                    const bool with_tangent)
  {
    op.stiffness_matrix().vmult(r, u);
    r -= body_force;
    auto *tangent = with_tangent ? &op.tangent_reset_to_stiffness() : nullptr;
    const ContactState state = add_support(u, r, tangent);
    if (plasticity)
      {
        plasticity->evaluate(u, plastic_force, true, tangent);
        r -= plastic_force;
      }
    op.get_constraints().set_zero(r);
    return state;
  }

  template <int dim>
  unsigned int
  WallContactProblem<dim>::solve(const double       tolerance,
                                 const unsigned int max_iterations)
  {
    PETScWrappers::MPI::Vector r       = op.create_vector(),
                               r_trial = op.create_vector(),
                               du      = op.create_vector(),
                               trial   = op.create_vector();

    std::unique_ptr<Factorization> tangent;
    residual(solution, r, true);
    for (iterations = 0; iterations < max_iterations; ++iterations)
      {
        if (r.l2_norm() <= tolerance * force_scale)
          return iterations;
        // Newton step with the consistent tangent (residual() left it),
        // factorized as the impact's matrices are; its pattern stays, so
        // after the first step only the numeric factorization is redone.
        // MUMPS on one rank too in 3D, where PETSc's own Cholesky is slow.
        if (!tangent)
          tangent = std::make_unique<Factorization>(
            MatrixSum{{1., &op.tangent_matrix()}},
            communicator,
            op.get_dof_handler().get_fe().n_components(),
            dim == 3);
        else
          tangent->refactorize({{1., &op.tangent_matrix()}});
        r *= -1.;
        tangent->solve(r, du);
        r *= -1.;
        op.get_constraints().distribute(du);

        // The energy (with plastic strains: the incremental energy of the
        // return mapping) is convex along du; its slope is r(u + s du) . du.
        // Minimize it: s = 1 if the slope there is still negative, else the
        // slope's root in (0, 1) by regula falsi (Illinois).
        auto slope = [&](const double s) {
          trial = solution;
          trial.add(s, du);
          residual(trial, r_trial, false);
          return r_trial * du;
        };
        double step = 1.;
        double s0 = 0., f0 = r * du, s1 = 1., f1 = slope(1.);
        if (f1 > 0.)
          for (unsigned int k = 0; k < 40; ++k)
            {
              step           = s1 - f1 * (s1 - s0) / (f1 - f0);
              const double f = slope(step);
              if (std::abs(f) <= 1e-3 * std::abs(r * du))
                break;
              if ((f > 0.) == (f1 > 0.))
                f0 *= 0.5; // Illinois: keep the other end moving
              else
                {
                  s0 = s1;
                  f0 = f1;
                }
              s1 = step;
              f1 = f;
            }
        trial = solution;
        trial.add(step, du);
        solution = trial;
        residual(solution, r, true);
      }
    if (r.l2_norm() <= tolerance * force_scale)
      return iterations;
    throw RunError(
      "quasistatic contact: Newton's method did not converge for load " +
      Utilities::to_string(load) + " in " + std::to_string(max_iterations) +
      " iterations (relative residual " +
      Utilities::to_string(r.l2_norm() / force_scale) + ")");
  }

  template <int dim>
  double
  WallContactProblem<dim>::accept()
  {
    // The trial states and f_p are those of solve()'s last residual, at
    // the solution.
    return plasticity ? plasticity->accept() / domain_share() : 0.;
  }

  template <int dim>
  std::pair<double, double>
  WallContactProblem<dim>::approach() const
  {
    const auto          &geometry = parameters.geometry;
    const double         R        = geometry.radius();
    const Point<dim>     center   = embedded<dim>(geometry.center());
    const auto           u        = op.create_ghosted(solution);
    const Tensor<1, dim> u_contact =
      op.vertex_displacement(u, center - R * wall.normal);
    const Tensor<1, dim> u_far =
      op.vertex_displacement(u, center + R * wall.normal);
    return {-(op.mean_displacement(u) * wall.normal) / R,
            ((u_contact - u_far) * wall.normal) / R};
  }

  template <int dim>
  const PETScWrappers::MPI::Vector &
  WallContactProblem<dim>::displacement() const
  {
    return solution;
  }

  template <int dim>
  const PETScWrappers::MPI::Vector &
  WallContactProblem<dim>::body_force_vector() const
  {
    return body_force;
  }

  template <int dim>
  PETScWrappers::MPI::Vector
  WallContactProblem<dim>::support_force_vector() const
  {
    PETScWrappers::MPI::Vector force = op.create_vector();
    add_support(solution, force, nullptr);
    op.get_constraints().set_zero(force);
    return force;
  }

  template <int dim>
  ContactState
  WallContactProblem<dim>::contact_state() const
  {
    if (load == 0.)
      return {};
    return contact->assemble(op.create_ghosted(solution), nullptr, nullptr);
  }

  template <int dim>
  double
  WallContactProblem<dim>::elastic_energy() const
  {
    // The condensed K's rows of constrained DoFs are not the energy's:
    // their entries are left out.
    PETScWrappers::MPI::Vector u = solution, Ku = op.create_vector();
    op.get_constraints().set_zero(u);
    op.stiffness_matrix().vmult(Ku, u);
    double elastic = 0.5 * (Ku * u);
    if (plasticity)
      elastic += -(plastic_force * u) + plasticity->plastic_strain_energy();
    return elastic / domain_share();
  }

  template <int dim>
  double
  WallContactProblem<dim>::largest_plastic_strain() const
  {
    return plasticity ? plasticity->largest_equivalent_plastic_strain() : 0.;
  }

  template <int dim>
  ContactLawPoint
  WallContactProblem<dim>::results() const
  {
    const double       R     = parameters.geometry.radius();
    const ContactState state = contact_state();

    ContactLawPoint point;
    point.load                                      = load;
    std::tie(point.delta_com, point.delta_diameter) = approach();
    point.half_width                                = state.half_width() / R;
    point.penetration                               = state.max_penetration / R;
    point.force_balance     = state.force / (domain_share() * force(load)) - 1.;
    point.h_contact         = h_contact / R;
    point.n_dofs            = n_dofs();
    point.newton_iterations = iterations;

    // Where the body first yields: the largest von Mises stress against
    // Hertz's p0 and a.
    if constexpr (dim == 2)
      {
        const auto        &geometry      = parameters.geometry;
        const StressPeak   peak          = largest_von_mises(op.get_mapping(),
                                                  op.get_dof_handler(),
                                                  {parameters.material},
                                                  op.create_ghosted(solution));
        const double       a             = theory->half_width(load) * R;
        const Point<2>     contact_point = geometry.center() - R * wall.normal;
        const Tensor<1, 2> offset        = peak.location - contact_point;
        const double       depth         = offset * wall.normal;
        point.von_mises_max =
          peak.von_mises / (theory->pressure(0., load) * pressure_unit());
        point.von_mises_depth  = depth / a;
        point.von_mises_offset = (offset - depth * wall.normal).norm() / a;
      }
    return point;
  }

  template <int dim>
  std::vector<std::pair<double, double>>
  WallContactProblem<dim>::pressure_profile() const
  {
    return contact->pressure_profile(op.create_ghosted(solution));
  }

  template <int dim>
  double
  WallContactProblem<dim>::pressure_unit() const
  {
    return theory->pressure_unit(force(load), parameters.geometry.radius());
  }

  template <int dim>
  std::string
  WallContactProblem<dim>::write_state(const std::string &directory,
                                       const unsigned int index) const
  {
    std::vector<CellField> cell_fields;
    if (plasticity)
      cell_fields = plastic_cell_fields(*plasticity);
    return write_deformed_state(op,
                                {parameters.material},
                                op.create_ghosted(solution),
                                directory,
                                "contact",
                                index,
                                {},
                                nullptr,
                                plasticity ? &cell_fields : nullptr);
  }
  template class WallContactProblem<2>;
  template class WallContactProblem<3>;
} // namespace DiskImpact
