#include "quasistatic/quasistatic_pair.h"

#include "base/run_error.h"
#include "contact/contact_operator.h"
#include "impact/impact_estimates.h"
#include "impact/impact_mesh.h"
#include "output/state_output.h"
#include "quasistatic/quasistatic_contact.h"
#include "reference/wall_contact_theory.h"
#include "run/parameters.h"

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace DiskImpact
{
  using namespace dealii;

  QuasistaticPair::QuasistaticPair(const Parameters &parameters,
                                   const double      load,
                                   MPI_Comm          communicator)
      : parameters(parameters)
      , load(load)
      , pair(contact_bodies(parameters))
      , total_force(
          load *
          Reference::wall_contact_theory(parameters.geometry.is_axisymmetric())
            ->force_unit(pair.first.modulus, pair.first.radius))
      , domain_force(parameters.geometry.domain_share() * total_force)
      , effective_radius(1. /
                         (1. / pair.first.radius + 1. / pair.second.radius))
      , communicator(communicator)
      , triangulation(communicator,
                      Triangulation<2>::limit_level_difference_at_vertices)
      , op(parameters.finite_element.degree)
  {
    const auto      &geometry = parameters.geometry;
    const auto      &partner  = parameters.partner;
    const bool       sphere   = geometry.is_axisymmetric();
    const RigidWall<2> wall     = parameters.contact.wall();
    const auto      &n        = wall.normal;
    const auto &[b1, b2]      = pair;
    a_hertz = Reference::two_body_half_width(sphere, total_force, b1, b2);
    approach_scale = sphere ?
                       Reference::two_sphere_approach(total_force, b1, b2) :
                       Reference::two_disk_approach(total_force, b1, b2);

    parameters.task_parameters<QuasistaticContact>().create_mesh(parameters,
                                                                 load,
                                                                 triangulation);
    // The far poles hold the bodies' translations (they carry no force in
    // the solution, see the class comment).
    op.setup(triangulation,
             geometry,
             false,
             {geometry.center() + geometry.radius() * n,
              partner.center() - partner.radius() * n});
    op.assemble(std::vector<Material>{parameters.material, partner.material()});
    h_contact = smallest_edge_face(op);

    // Candidates: edge points whose undeformed gap is below three times
    // that of the edge of Hertz's contact, a^2 / (2 R_eff), beyond the law's
    // reach (out to about 1.7 a); solve() checks that the contact stays
    // within the inner half.
    const auto law = parameters.contact.law(
      {contact_modulus(parameters), h_contact, geometry.radius()});
    const double bound =
      law->reach() + 1.5 * a_hertz * a_hertz / effective_radius;
    zone = std::make_unique<ContactZone>(
      op, wall, law, geometry.center(), bound, true);
    std::vector<unsigned int> all(zone->candidate_dofs().size());
    std::iota(all.begin(), all.end(), 0u);
    zone->activate(all);

    solver = std::make_unique<CondensedSolver>(
      op.stiffness_matrix(),
      op.locally_owned_dofs(),
      communicator,
      op.get_dof_handler().get_fe().n_components());
    solver->set_observed_dofs(zone->candidate_dofs());
    solver->add_dofs(all);

    // Uniform body forces of P in total (the computed domain's share)
    // toward the other body, each divided by its discrete volume.
    auto body_force = op.create_vector(), partner_force = op.create_vector();
    op.assemble_body_force(-domain_force / op.volume(0) * n, body_force, 0);
    op.assemble_body_force(domain_force / op.volume(1) * n, partner_force, 1);
    body_force += partner_force;
    y = op.create_vector();
    solver->solve(body_force, y);
    op.get_constraints().distribute(y);
    y_C = solver->observe(y);

    // t: n on every DoF of the body, its pin's included.
    translation                               = op.create_vector();
    const auto                          &dofs = op.get_dof_handler();
    const auto                          &fe   = dofs.get_fe();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == 0)
        {
          cell->get_dof_indices(indices);
          for (unsigned int k = 0; k < indices.size(); ++k)
            if (op.locally_owned_dofs().is_element(indices[k]))
              translation(indices[k]) =
                n[fe.system_to_component_index(k).first];
        }
    translation.compress(VectorOperation::insert);
    t_C      = solver->observe(translation);
    solution = op.create_vector();
  }

  ContactState
  QuasistaticPair::residual(const Vector<double> &u_C,
                            const double          s,
                            Vector<double>       &r,
                            FullMatrix<double>   *jacobian) const
  {
    const unsigned int n    = u_C.size();
    const auto         step = zone->step_force(
      u_C, u_C, ContactAverage::trapezoidal, 1., jacobian != nullptr);
    const Vector<double>     &P        = step.force;
    const FullMatrix<double> &s_matrix = solver->condensed_matrix();
    Vector<double>            sp(n);
    s_matrix.vmult(sp, P);
    r.reinit(n + 1);
    for (unsigned int i = 0; i < n; ++i)
      r[i] = u_C[i] - y_C[i] - sp[i] - s * t_C[i];
    r[n] = (t_C * P - domain_force) / domain_force;
    if (jacobian != nullptr)
      {
        // d/du_C: I - S dP/du and t_C . dP/du / P; d/ds: -t_C and 0.
        const FullMatrix<double> &dP = step.jacobian;
        FullMatrix<double>        SdP(n, n);
        s_matrix.mmult(SdP, dP);
        FullMatrix<double> J(n + 1, n + 1);
        for (unsigned int i = 0; i < n; ++i)
          {
            for (unsigned int j = 0; j < n; ++j)
              J(i, j) = (i == j ? 1. : 0.) - SdP(i, j);
            J(i, n) = -t_C[i];
          }
        for (unsigned int j = 0; j < n; ++j)
          {
            double tdP = 0.;
            for (unsigned int i = 0; i < n; ++i)
              tdP += t_C[i] * dP(i, j);
            J(n, j) = tdP / domain_force;
          }
        *jacobian = std::move(J);
      }
    return step.state;
  }

  double
  QuasistaticPair::residual_norm(const Vector<double> &r) const
  {
    double largest = 0.;
    for (unsigned int i = 0; i + 1 < r.size(); ++i)
      largest = std::max(largest, std::abs(r[i]));
    return std::max(largest / approach_scale, std::abs(r[r.size() - 1]));
  }

  unsigned int
  QuasistaticPair::solve(const double       tolerance,
                         const unsigned int max_iterations)
  {
    const unsigned int n = y_C.size();
    // The gaps move with s one to one (t . b = 1 on the body's part of a
    // row, the partner's part does not move).
    double s =
      -0.5 * a_hertz * a_hertz / effective_radius - zone->smallest_gap(y_C);
    Vector<double> u_C(n);
    for (unsigned int i = 0; i < n; ++i)
      u_C[i] = y_C[i] + s * t_C[i];

    Vector<double>     r, r_trial, dz(n + 1), u_trial(n);
    FullMatrix<double> J;
    residual(u_C, s, r, &J);
    double norm = residual_norm(r);
    for (iterations = 0; iterations < max_iterations && norm > tolerance;
         ++iterations)
      {
        // The same dense system on every rank: no communication.
        Vector<double> minus_r(r);
        minus_r *= -1.;
        J.gauss_jordan();
        J.vmult(dz, minus_r);
        double step = 1.;
        for (unsigned int halving = 0; halving < 30; ++halving, step *= 0.5)
          {
            for (unsigned int i = 0; i < n; ++i)
              u_trial[i] = u_C[i] + step * dz[i];
            residual(u_trial, s + step * dz[n], r_trial, nullptr);
            if (residual_norm(r_trial) < (1. - 1e-4 * step) * norm)
              break;
          }
        u_C = u_trial;
        s += step * dz[n];
        residual(u_C, s, r, &J);
        norm = residual_norm(r);
      }
    if (norm > tolerance)
      throw RunError(
        "quasistatic contact: Newton's method did not converge for load " +
        Utilities::to_string(load) + " in " + std::to_string(max_iterations) +
        " iterations (relative residual " + Utilities::to_string(norm) + ")");
    zone->check_within_bound(u_C);

    // u = y + X P + s t on the whole mesh.
    const auto step =
      zone->step_force(u_C, u_C, ContactAverage::trapezoidal, 1., false);
    solution = y;
    solver->add_columns(step.force, solution);
    op.get_constraints().distribute(solution);
    solution.add(s, translation);
    return iterations;
  }

  PairContactPoint
  QuasistaticPair::results() const
  {
    const auto          &geometry = parameters.geometry;
    const auto          &n        = parameters.contact.wall().normal;
    const double         R        = geometry.radius();
    const auto           u        = op.create_ghosted(solution);
    const Vector<double> u_C      = solver->observe(solution);
    const ContactState   state =
      zone->step_force(u_C, u_C, ContactAverage::trapezoidal, 1., false).state;
    const double   mean_body    = op.mean_displacement(u, 0) * n;
    const double   mean_partner = op.mean_displacement(u, 1) * n;
    const Point<2> partner_contact =
      geometry.contact_point() - parameters.partner.gap() * n;

    PairContactPoint point;
    point.load     = load;
    point.approach = (mean_partner - mean_body) / R;
    point.shares   = {
        {(op.vertex_displacement(u, geometry.contact_point(), 0) * n -
        mean_body) /
           R,
         (mean_partner - op.vertex_displacement(u, partner_contact, 1) * n) / R}};
    point.half_width        = state.half_width() / R;
    point.penetration       = state.max_penetration / R;
    point.force_balance     = state.force / domain_force - 1.;
    point.h_contact         = h_contact / R;
    point.n_dofs            = op.get_dof_handler().n_dofs();
    point.newton_iterations = iterations;
    return point;
  }

  double
  QuasistaticPair::hertz_half_width() const
  {
    return a_hertz;
  }

  double
  QuasistaticPair::force() const
  {
    return total_force;
  }

  const std::pair<Reference::ContactBody, Reference::ContactBody> &
  QuasistaticPair::bodies() const
  {
    return pair;
  }

  std::string
  QuasistaticPair::write_state(const std::string &directory,
                               const unsigned int index) const
  {
    return write_deformed_state(op,
                                {parameters.material,
                                 parameters.partner.material()},
                                op.create_ghosted(solution),
                                directory,
                                "contact",
                                index);
  }
} // namespace DiskImpact
