#include "tasks/impact_simulation.h"

#include "base/parameters.h"
#include "base/run_error.h"
#include "contact/complementarity.h"
#include "dynamics/anderson_acceleration.h"
#include "output/atomic_file.h"
#include "output/hdf5_output.h"
#include "output/state_output.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// What makes an impact's result unphysical, for the messages.
    const std::string likely_causes =
      "the body is far too stiff or too soft: volumetric locking (a Poisson "
      "ratio near 0.5 in plane strain with low 'Degree'), too coarse a mesh, "
      "a time step or 'Penalty factor' far off";

    /// The time series of one impact.
    CsvTable
    time_series_table()
    {
      return CsvTable({"time",
                       "x_com",
                       "v_com",
                       "contact_force",
                       "contact_half_width",
                       "energy_kinetic",
                       "energy_translational",
                       "energy_strain",
                       "energy_contact",
                       "energy_dissipated",
                       "energy_total"});
    }

    /// The locally owned entries of @p x of all ranks, in DoF order, on
    /// rank 0 (empty elsewhere).
    std::vector<double>
    gather_on_root(const PETScWrappers::MPI::Vector &x, MPI_Comm communicator)
    {
      std::vector<double> local;
      for (const auto i : x.locally_owned_elements())
        local.push_back(x[i]);
      std::vector<double> all;
      for (const auto &part : Utilities::MPI::gather(communicator, local, 0))
        all.insert(all.end(), part.begin(), part.end());
      return all;
    }

    /// impact.h5: the summary, the time series, the mode energies (their
    /// numeric columns; the families as an attribute) and the final state.
    void
    write_hdf5(const std::string         &filename,
               const ImpactSummary       &summary,
               const CsvTable            &series,
               const CsvTable            &modes,
               const std::vector<double> &displacement,
               const std::vector<double> &velocity,
               const std::string         &parameters_json,
               const std::string         &units,
               const UnitSystem          &unit_system)
    {
      Hdf5Output file(filename);
      file.write_table("summary", Impact::summary_table(summary));
      file.write_table("time_series", series);
      if (modes.n_rows() > 0)
        {
          std::vector<std::string>         names;
          std::vector<std::vector<double>> columns;
          for (const auto &name : modes.column_names())
            if (name != "family")
              {
                names.push_back(name);
                columns.push_back(modes.column(name));
              }
          file.write_table("mode_energies", names, columns);
          std::string families;
          for (const auto &family : modes.text_column("family"))
            families += (families.empty() ? "" : ",") + family;
          file.set_attribute("mode_energies", "family", families);
        }
      file.write_vector("final_state", "displacement", displacement);
      file.write_vector("final_state", "velocity", velocity);
      file.set_attribute("/", "units", units);
      file.set_si_unit_attributes(unit_system);
      file.set_attribute("/", "parameters", parameters_json);
      file.finish();
    }
  } // namespace

  ImpactSimulation::ImpactSimulation(const Parameters &parameters,
                                     const Impact     &impact,
                                     MPI_Comm          communicator,
                                     const bool        write_outputs,
                                     std::shared_ptr<ImpactOperators> operators)
      : parameters(parameters)
      , impact(impact)
      , communicator(communicator)
      , with_outputs(write_outputs)
      , R(parameters.geometry.radius())
      , E2(parameters.material.in_plane_young_modulus())
      , c(parameters.material.velocity_unit())
      , v0(impact.velocity() * c)
      , mass(parameters.material.density() * parameters.geometry.volume())
      , factor(1. / parameters.geometry.domain_share())
      , force_unit(Impact::force_unit(parameters))
      , operators(
          operators ?
            std::move(operators) :
            std::make_shared<ImpactOperators>(parameters, impact, communicator))
      , op(this->operators->op)
      , constraint_map(*this->operators->constraint_map)
      , series(time_series_table())
  {
    summary.velocity = impact.velocity();
    (parameters.geometry.is_axisymmetric() ? summary.ramirez_u :
                                             summary.schwager_alpha) =
      impact.dissipation_parameter(parameters);
  }

  ImpactSummary
  ImpactSimulation::run()
  {
    estimate_collision();
    setup_operators();
    set_initial_state();
    record(0., ContactState());
    if (impact.output_interval > 0)
      snapshot();
    dt = parameters.time_integrator.time_step(contact_time_estimate);
    factorize();

    const auto start = std::chrono::steady_clock::now();
    do
      {
        advance();
        record(t, state);
        if (projection && state.force_average > 0.)
          projection->add_sample(u, v, dt);
        if (impact.output_interval > 0 &&
            summary.steps % impact.output_interval == 0)
          snapshot();
      }
    while (!collision_over());
    summary.wall_time_loop =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    finish();
    check_result();
    snapshot();
    if (with_outputs)
      write_outputs();
    return summary;
  }

  void
  ImpactSimulation::estimate_collision()
  {
    const auto estimate               = impact.estimate_collision(parameters);
    contact_time_estimate             = estimate.contact_time;
    approach_estimate                 = estimate.largest_compression;
    summary.one_dof_contact_time      = estimate.one_dof_contact_time;
    summary.one_dof_delta_max         = estimate.one_dof_delta_max;
    summary.one_dof_epsilon           = estimate.one_dof_epsilon;
    summary.one_dof_epsilon_overlap   = estimate.one_dof_epsilon_overlap;
    summary.one_dof_epsilon_unloading = estimate.one_dof_epsilon_unloading;
  }

  void
  ImpactSimulation::setup_operators()
  {
    const auto &geometry  = parameters.geometry;
    const auto &law       = operators->law;
    const bool  pair      = parameters.partner.is_body();
    summary.massless_dofs = op.n_massless_dofs();
    summary.n_dofs        = op.get_dof_handler().n_dofs();
    // The modes to project on, of the operator the time stepping uses.
    if (with_outputs && impact.projected_modes > 0 && !pair)
      projection = std::make_unique<ModalProjection>(
        op,
        geometry,
        std::pow(parameters.material.transverse_wave_speed() / R, 2),
        impact.projected_modes);
    zone = std::make_unique<ContactZone>(op,
                                         parameters.contact.wall(),
                                         law,
                                         geometry.center(),
                                         operators->candidate_bound,
                                         pair);
    if (law.kind == WallLawKind::constraint &&
        parameters.time_integrator.conserves_energy())
      {
        massless   = std::make_unique<MasslessZone>(op, zone->candidate_dofs());
        point_rows = zone->point_rows();
        static_compliance = massless->compliance(point_rows);
      }
    if (pair)
      bodies =
        std::make_unique<BodyMotion>(op, parameters.contact.wall().normal, 2);
  }

  void
  ImpactSimulation::set_initial_state()
  {
    for (PETScWrappers::MPI::Vector *x :
         std::initializer_list<PETScWrappers::MPI::Vector *>{&u,
                                                             &v,
                                                             &a,
                                                             &u_new,
                                                             &v_new,
                                                             &a_new,
                                                             &along_normal,
                                                             &b,
                                                             &stiffness_u,
                                                             &mass_u,
                                                             &mass_v,
                                                             &mass_a,
                                                             &mass_u_new,
                                                             &mass_v_new,
                                                             &mass_a_new})
      *x = op.create_vector();
    u_D.reinit(zone->candidate_dofs().size());
    point_forces.reinit(zone->n_points());
    point_forces_new.reinit(zone->n_points());
    work               = op.create_vector();
    product            = op.create_vector();
    const auto &normal = parameters.contact.wall().normal;
    VectorTools::interpolate(op.get_mapping(),
                             op.get_dof_handler(),
                             Functions::ConstantFunction<2>(
                               std::vector<double>{normal[0], normal[1]}),
                             along_normal);
    op.get_constraints().distribute(along_normal);
    if (bodies)
      {
        // The centre-of-mass frame: v1 m1 = v2 m2, v1 + v2 = v_i.
        const double m1 = bodies->mass(0), m2 = bodies->mass(1);
        v.add(-v0 * m2 / (m1 + m2), bodies->normal_field(0));
        v.add(v0 * m1 / (m1 + m2), bodies->normal_field(1));
      }
    else
      v.add(-v0, along_normal);
    // The centre of mass's motion along the wall normal is the momentum
    // (M x) . n over the mass n . M n (valid for a redistributed mass too).
    normal_momentum = op.mass_functional(along_normal);
    normal_mass     = normal_momentum * along_normal;
    energy_initial  = factor * quadratic_form(op.mass_matrix(), v, mass_v);
    v_com_initial   = mean_along_normal(v);
  }

  double
  ImpactSimulation::quadratic_form(
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const PETScWrappers::MPI::Vector       &x) const
  {
    return quadratic_form(matrix, x, product);
  }

  double
  ImpactSimulation::quadratic_form(
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const PETScWrappers::MPI::Vector       &x,
    PETScWrappers::MPI::Vector             &matrix_x) const
  {
    // On the condensed matrices, x with its constrained entries zeroed
    // gives the form of the unconstrained field.
    constraint_map.zeroed(x, work);
    matrix.vmult(matrix_x, work);
    return 0.5 * (work * matrix_x);
  }

  double
  ImpactSimulation::mean_along_normal(const PETScWrappers::MPI::Vector &x) const
  {
    // Two bodies: the body's centre of mass relative to the partner's.
    if (bodies)
      return bodies->center_of_mass(0, x) - bodies->center_of_mass(1, x);
    return (normal_momentum * x) / normal_mass;
  }

  double
  ImpactSimulation::translational_energy(const double v_com) const
  {
    if (!bodies)
      return 0.5 * mass * v_com * v_com;
    double energy = 0.;
    for (unsigned int body = 0; body < 2; ++body)
      energy += 0.5 * factor * bodies->mass(body) *
                std::pow(bodies->center_of_mass(body, v), 2);
    return energy;
  }

  void
  ImpactSimulation::factorize()
  {
    if (solver)
      {
        factorizations_before += solver->n_factorizations();
        solves_before += solver->n_triangular_solves();
        solve_time_before += solver->triangular_solve_time();
      }
    // A = cK K + cM M (+ cD D): M's pattern is a subset of K's, D's is K's.
    const auto &integrator = parameters.time_integrator;
    MatrixSum   A{{integrator.stiffness_coefficient(), &op.stiffness_matrix()},
                {integrator.mass_coefficient(dt), &op.mass_matrix()}};
    if (op.has_damping())
      A.push_back({integrator.damping_coefficient(dt),
                   &op.damping_matrix(),
                   SAME_NONZERO_PATTERN});

    // The old solver's columns belong to the old factorization.
    solver.reset();
    auto &factorization = operators->factorization;
    if (factorization)
      factorization->refactorize(A);
    else
      factorization = std::make_shared<Factorization>(
        A, communicator, op.get_dof_handler().get_fe().n_components());
    solver = std::make_unique<CondensedSolver>(factorization,
                                               op.locally_owned_dofs(),
                                               communicator);
    solver->set_observed_dofs(zone->candidate_dofs());
    solver->add_dofs(zone->active_dofs());
  }

  bool
  ImpactSimulation::attempt_step()
  {
    const auto &integrator = parameters.time_integrator;
    // Right-hand side M w - D z - af K u0, with M w from the images of u0,
    // v0, a0 and K u0 from update_stiffness_image(). (They differ from M w and
    // K u0 in the constrained rows only, which the solve keeps to themselves
    // and distribute() overwrites.)
    integrator.inertia_vector<PETScWrappers::MPI::Vector>(
      mass_u, mass_v, mass_a, dt, b);
    b.add(-integrator.old_stiffness_weight(), stiffness_u);
    if (op.has_damping())
      {
        integrator.damping_vector<PETScWrappers::MPI::Vector>(
          u, v, a, dt, work);
        op.damping_matrix().vmult(product, work);
        b.add(-1., product);
      }
    // The response without contact force y: one solve with the factorized
    // matrix, into u_new. The end state is y + X P(u1_C): a dense system
    // on C.
    solver->solve(b, u_new);
    // The candidates' DoFs are unconstrained (ConstrainedRow), so y needs
    // its constraints distributed only as part of the end state below.
    const Vector<double> y_D  = solver->observe(u_new);
    Vector<double>       u1_D = y_D;
    Vector<double>       P;
    if (parameters.contact.law_kind() == WallLawKind::constraint)
      {
        // The trapezoidal step, then (energy conserving) the exact mean
        // along the step: the DoFs with mass see the mean point forces
        // instead of (mu0 + mu1) / 2. Their difference dmu, held by the
        // massless zone, moves the end state by
        // A^{-1} (-K_IM e) = X B^T dmu - 2 e, e = K_MM^{-1} B^T dmu (the
        // massless rows of A are K / 2): no further solve with A.
        Vector<double>       applied(zone->n_points());
        Vector<double>       y_D_corrected = y_D;
        AndersonAcceleration acceleration(5);
        for (unsigned int pass = 0;; ++pass)
          {
            if (!attempt_constrained_step(y_D_corrected, u1_D, P))
              return false;
            if (!massless || pass == integrator.max_newton_iterations())
              break;
            // The fixed point dmu = mean(dmu) - trapezoid, by Anderson's
            // acceleration.
            const Vector<double> change = mean_force_correction(u1_D, applied);
            if (change.linfty_norm() == 0.)
              break;
            applied            = acceleration.next(applied, change);
            const auto missing = zone->inactive_dofs_of(applied);
            zone->activate(missing);
            solver->add_dofs(missing);
            y_D_corrected = y_D;
            y_D_corrected +=
              solver->observed_response(zone->constraint_force(applied));
            y_D_corrected.add(-2.,
                              massless->response_on_candidates(point_rows,
                                                               applied));
          }
        if (applied.linfty_norm() > 0.)
          {
            solver->add_columns(zone->constraint_force(applied), u_new);
            massless->add_response(point_rows, applied, -2., u_new);
          }
        if (P.size() > 0)
          solver->add_columns(P, u_new);
        constraint_map.distribute(u_new);
        state = zone->constraint_state(point_forces,
                                       point_forces_new,
                                       zone->restrict_to_active(u1_D),
                                       integrator.contact_new_weight());
        // The mean force's share beyond the trapezoidal one.
        for (const double dmu : applied)
          state.force_average += dmu;
        u1_D_new = u1_D;
        return true;
      }
    for (;;)
      {
        // Points that touch at the start, the contact-free end or the end
        // found so far take part: their DoFs join C (one solve each).
        const auto missing = zone->dofs_to_activate({&u_D, &y_D, &u1_D});
        zone->activate(missing);
        solver->add_dofs(missing);
        if (zone->n_active_dofs() == 0)
          break;
        const Vector<double> u0_C = zone->restrict_to_active(u_D);
        const Vector<double> y_C  = zone->restrict_to_active(y_D);
        Vector<double>       u1_C = y_C;
        unsigned int         iterations;
        const auto           force = [&](const Vector<double> &u_C) {
          auto f = zone->step_force(u0_C,
                                    u_C,
                                    integrator.contact_average(),
                                    integrator.contact_new_weight(),
                                    true);
          return std::make_pair(f.force, f.jacobian);
        };
        if (!solver->solve_condensed(y_C,
                                     force,
                                     integrator.newton_tolerance() *
                                       approach_estimate,
                                     integrator.max_newton_iterations(),
                                     u1_C,
                                     iterations))
          return false;
        summary.newton_iterations += iterations;
        P    = force(u1_C).first;
        u1_D = y_D;
        u1_D += solver->observed_response(P);
        if (zone->dofs_to_activate({&u1_D}).empty())
          break;
      }
    if (P.size() > 0)
      solver->add_columns(P, u_new);
    constraint_map.distribute(u_new);
    contact_force             = P;
    const Vector<double> u0_C = zone->restrict_to_active(u_D);
    state                     = zone
              ->step_force(u0_C,
                           zone->restrict_to_active(u1_D),
                           integrator.contact_average(),
                           integrator.contact_new_weight(),
                           false)
              .state;
    u1_D_new = u1_D;
    return true;
  }

  bool
  ImpactSimulation::attempt_constrained_step(const Vector<double> &y_D,
                                             Vector<double>       &u1_D,
                                             Vector<double>       &P)
  {
    // The contact DoFs carry no mass: at each step's end they are in
    // equilibrium with the point forces mu1 there, so the step force is
    // P = af F(mu0) + (1 - af) F(mu1), the end state u1 = y + X P and its
    // gaps g = q + W mu1 with W = (1 - af) B S B^T: a complementarity
    // problem on the points that can touch (docs/theory/impact-method.md).
    const double new_weight = parameters.time_integrator.contact_new_weight();
    for (;;)
      {
        const auto missing = zone->dofs_to_activate({&u_D, &y_D, &u1_D});
        zone->activate(missing);
        solver->add_dofs(missing);
        point_forces_new.reinit(zone->n_points());
        if (zone->n_active_dofs() == 0)
          return true;
        const Vector<double> F0 = zone->constraint_force(point_forces);
        Vector<double> base_C = zone->restrict_to_active(y_D); // y_C + af S F0
        Vector<double> s_f0(F0.size());
        solver->condensed_matrix().vmult(s_f0, F0);
        base_C.add(1. - new_weight, s_f0);
        const auto system = zone->constraint_system(base_C);
        // W = (1 - af) B S B^T.
        const unsigned int n = system.points.size();
        FullMatrix<double> sbt(solver->n_contact_dofs(), n), W(n, n);
        solver->condensed_matrix().mTmult(sbt, system.rows);
        system.rows.mmult(W, sbt);
        W *= new_weight;
        std::vector<bool> warm(n);
        for (unsigned int r = 0; r < n; ++r)
          warm[r] = point_forces[system.points[r]] > 0.;
        const auto solution =
          solve_complementarity(W,
                                system.gaps,
                                parameters.time_integrator.newton_tolerance() *
                                  approach_estimate,
                                warm);
        if (!solution.converged)
          return false;
        summary.newton_iterations += solution.iterations;
        for (unsigned int r = 0; r < n; ++r)
          point_forces_new[system.points[r]] = solution.force[r];
        P = F0;
        P *= 1. - new_weight;
        P.add(new_weight, zone->constraint_force(point_forces_new));
        u1_D = y_D;
        u1_D += solver->observed_response(P);
        if (zone->dofs_to_activate({&u1_D}).empty())
          return true;
      }
  }

  Vector<double>
  ImpactSimulation::mean_force_correction(const Vector<double> &u1_D,
                                          const Vector<double> &applied) const
  {
    // Along the step the DoFs with mass move on a straight line, so the
    // massless zone's gaps without contact forces, q = g - W_s mu, are
    // linear in s from the start to the end state; the forces mu(s) solve
    // the static complementarity problem with them. AVF: the step force is
    // their mean, where the trapezoidal step used (mu0 + mu1) / 2.
    const unsigned int n  = zone->n_points();
    Vector<double>     q0 = zone->point_gaps(u_D), q1 = zone->point_gaps(u1_D);
    Vector<double>     response(n);
    static_compliance.vmult(response, point_forces);
    q0 -= response;
    static_compliance.vmult(response, point_forces_new);
    q1 -= response;
    const Vector<double> target =
      mean_along_segment(static_compliance,
                         q0,
                         q1,
                         parameters.time_integrator.newton_tolerance() *
                           approach_estimate);
    Vector<double> change(target);
    change.add(-0.5, point_forces, -0.5, point_forces_new);
    change -= applied;
    const double scale =
      std::max(point_forces.linfty_norm(), point_forces_new.linfty_norm());
    if (change.linfty_norm() <= 1e-12 * scale)
      change = 0.;
    return change;
  }

  void
  ImpactSimulation::advance()
  {
    const auto &integrator = parameters.time_integrator;
    while (!attempt_step())
      {
        if (++cuts > integrator.max_step_cuts())
          throw RunError(
            "impact: Newton's method did not converge at t = " +
            Utilities::to_string(t * c / R) +
            " R/c even with the time step halved " +
            std::to_string(integrator.max_step_cuts()) +
            " times; lower 'Time step fraction' or the 'Penalty factor'");
        dt *= 0.5;
        factorize();
      }
    // v_new and a_new are linear combinations of fields that satisfy the
    // (homogeneous) constraints, so they satisfy them too.
    integrator.update<PETScWrappers::MPI::Vector>(
      u, u_new, v, a, dt, v_new, a_new);
    constraint_map.zeroed(u_new, work);
    operators->mass_product->vmult(mass_u_new, work);
    integrator.update<PETScWrappers::MPI::Vector>(
      mass_u, mass_u_new, mass_v, mass_a, dt, mass_v_new, mass_a_new);
    update_stiffness_image();
    impulse += dt * factor * state.force_average;
    if (op.has_damping())
      {
        // the step's viscous work, dt v^T D v at the damping's velocity
        integrator.damping_velocity<PETScWrappers::MPI::Vector>(v, v_new, work);
        dissipated +=
          2. * dt * factor * quadratic_form(op.damping_matrix(), work);
      }
    u.exchange(u_new);
    v.exchange(v_new);
    a.exchange(a_new);
    mass_u.exchange(mass_u_new);
    mass_v.exchange(mass_v_new);
    mass_a.exchange(mass_a_new);
    u_D = u1_D_new;
    point_forces.swap(point_forces_new);
    t += dt;
    ++summary.steps;
  }

  void
  ImpactSimulation::update_stiffness_image()
  {
    const auto &integrator = parameters.time_integrator;
    if (op.has_damping() ||
        parameters.contact.law_kind() == WallLawKind::constraint)
      {
        quadratic_form(op.stiffness_matrix(), u_new, stiffness_u);
        return;
      }
    // The step solved A u1 = b + E_C P with A = cK K + cM M, so in the
    // unconstrained rows K u1 = (b + E_C P - cM M u1) / cK: no product
    // with K. (The constrained rows, which differ, are zeroed in u where
    // it meets them and kept to themselves by the solve.)
    stiffness_u = b;
    if (contact_force.size() > 0)
      solver->add_forces(contact_force, stiffness_u);
    stiffness_u.add(-integrator.mass_coefficient(dt), mass_u_new);
    stiffness_u /= integrator.stiffness_coefficient();
  }

  void
  ImpactSimulation::record(const double time, const ContactState &step)
  {
    constraint_map.zeroed(v, work);
    const double kinetic = 0.5 * factor * (work * mass_v);
    constraint_map.zeroed(u, work);
    const double strain = 0.5 * factor * (work * stiffness_u);
    const double v_com  = mean_along_normal(v);
    const double x_com  = mean_along_normal(u) / R;
    const double total  = kinetic + strain + factor * step.energy + dissipated;
    // The step's mean force (its impulse / dt): the time discretization fixes
    // this mean, not the end-of-step force (docs/theory/impact-method.md).
    const double force = factor * step.force_average / force_unit;
    energy_error =
      std::max(energy_error, std::abs(total - energy_initial) / energy_initial);
    energy_growth =
      std::max(energy_growth, (total - energy_initial) / energy_initial);
    // A run whose energy runs away (a thousandfold) is stopped here rather
    // than when its numbers overflow; a milder growth fails check_result().
    // The values are the same on every rank.
    if (!(energy_growth <= 1e3))
      throw RunError(
        "impact at v = " + approximately(v0 / c, 6) +
        " c fails the check 'energy growth': the total energy "
        "grew by " +
        approximately(energy_growth) +
        " times its initial value by t = " + approximately(time * c / R) +
        " R/c (the time stepping is unstable for this contact)");
    series.start_row();
    for (const double value : {time * c / R,
                               x_com,
                               v_com / c,
                               force,
                               step.half_width() / R,
                               kinetic,
                               translational_energy(v_com),
                               strain,
                               factor * step.energy,
                               dissipated,
                               total})
      series.add(value);
    summary.delta_max = std::max(summary.delta_max, -x_com);
    summary.force_max = std::max(summary.force_max, force);
  }

  bool
  ImpactSimulation::collision_over()
  {
    // The collision ends when the step-mean force returns to zero (Schwager &
    // Pöschel 2007): the last two positive values, at mid-step, extrapolated to
    // zero within the step in which the force vanished.
    const double mean_force = state.force_average;
    const double mid_time   = t - 0.5 * dt;
    if (mean_force > 0.)
      contact_end = -1.;
    else if (contact_end < 0. && previous_force > 0.)
      {
        const double slope =
          (previous_force - older_force) / (previous_time - older_time);
        contact_end = slope < 0. ?
                        std::min(t, previous_time - previous_force / slope) :
                        previous_time;
      }
    if (contact_end >= 0. && t >= contact_end * (1. + impact.margin))
      return true;
    if (t > 20. * contact_time_estimate)
      throw RunError("impact: the contact has not ended after " +
                     Utilities::to_string(20. * contact_time_estimate * c / R) +
                     " R/c");
    older_force    = previous_force;
    older_time     = previous_time;
    previous_force = mean_force;
    previous_time  = mid_time;
    return false;
  }

  void
  ImpactSimulation::snapshot()
  {
    if (!with_outputs)
      return;
    const auto  ghosted_u = op.create_ghosted(u);
    const auto &directory = parameters.run.output_directory;
    // The record's times and fields in the units of the files (SI for an
    // SI run).
    const FieldScales scales = parameters.units.field_scales();
    const double      time   = t * c / R * scales.time;
    if (impact.revolved_view_angle > 0.)
      {
        const auto [flat, revolved] =
          write_deformed_and_revolved_state(op,
                                            ImpactOperators::materials(
                                              parameters),
                                            ghosted_u,
                                            parameters.geometry.center(),
                                            R,
                                            impact.revolved_view_angle,
                                            directory,
                                            "impact",
                                            snapshots.size(),
                                            scales);
        snapshots.emplace_back(time, flat);
        revolved_snapshots.emplace_back(time, revolved);
      }
    else
      snapshots.emplace_back(time,
                             write_deformed_state(op,
                                                  ImpactOperators::materials(
                                                    parameters),
                                                  ghosted_u,
                                                  directory,
                                                  "impact",
                                                  snapshots.size(),
                                                  scales));
  }

  void
  ImpactSimulation::finish()
  {
    const double v_com_final = mean_along_normal(v);
    const double body_mass   = factor * normal_mass;
    summary.epsilon          = -v_com_final / v_com_initial;
    summary.contact_time     = contact_end * c / R;
    summary.energy_error     = energy_error;
    if (bodies)
      finish_pair();
    else
      {
        summary.impulse_error =
          std::abs(body_mass * (v_com_final - v_com_initial) - impulse) /
          (body_mass * v0);
        // The energy left in the body's vibration: all but its centre of
        // mass's kinetic energy.
        summary.vibration_fraction =
          (factor * (quadratic_form(op.mass_matrix(), v) +
                     quadratic_form(op.stiffness_matrix(), u)) -
           0.5 * body_mass * v_com_final * v_com_final) /
          energy_initial;
      }
    summary.factorizations = factorizations_before + solver->n_factorizations();
    summary.triangular_solves = solves_before + solver->n_triangular_solves();
    summary.time_step         = dt * c / R;
    summary.triangular_solve_time =
      (solve_time_before + solver->triangular_solve_time()) /
      summary.triangular_solves;
    summary.contact_dofs = solver->n_contact_dofs();
  }

  void
  ImpactSimulation::finish_pair()
  {
    // Each body's momentum change against the contact impulse (equal and
    // opposite on the two), relative to the reduced mass's m v_i; and the
    // energy left in each body's vibration: its energy less its centre of
    // mass's kinetic energy.
    const double m1      = factor * bodies->mass(0);
    const double m2      = factor * bodies->mass(1);
    const double reduced = m1 * m2 / (m1 + m2);
    double       error   = 0.;
    for (unsigned int body = 0; body < 2; ++body)
      {
        const double m = body == 0 ? m1 : m2;
        const double v_start =
          body == 0 ? -v0 * m2 / (m1 + m2) : v0 * m1 / (m1 + m2);
        const double v_end = bodies->center_of_mass(body, v);
        error              = std::max(error,
                         std::abs(m * (v_end - v_start) -
                                  (body == 0 ? impulse : -impulse)));
        const double vibration =
          factor * (bodies->quadratic_form(body, op.mass_matrix(), v) +
                    bodies->quadratic_form(body, op.stiffness_matrix(), u)) -
          0.5 * m * v_end * v_end;
        (body == 0 ? summary.vibration_fraction :
                     summary.partner_vibration_fraction) =
          vibration / energy_initial;
      }
    summary.impulse_error  = error / (reduced * v0);
    summary.momentum_error = std::abs(m1 * bodies->center_of_mass(0, v) +
                                      m2 * bodies->center_of_mass(1, v)) /
                             (reduced * v0);
  }

  void
  ImpactSimulation::check_result() const
  {
    // Every value below is the same on all ranks: the error is collective.
    const auto fail = [&](const std::string &check, const std::string &what) {
      throw RunError("impact at v = " + approximately(v0 / c, 6) +
                     " c fails the check '" + check + "': " + what);
    };
    const double eps = summary.epsilon;
    if (!(eps >= 0. && eps <= 1. + 1e-6))
      fail("0 <= epsilon <= 1",
           "epsilon = " + approximately(eps, 6) +
             " is impossible for a passive body; " + likely_causes);
    const auto &integrator = parameters.time_integrator;
    if (integrator.conserves_energy() &&
        !(summary.energy_error <= integrator.energy_error_tolerance()))
      fail("energy balance",
           "the total energy changed by " +
             approximately(summary.energy_error) +
             " of the initial energy, more than 'Energy tolerance' = " +
             approximately(integrator.energy_error_tolerance()) +
             "; lower 'Newton tolerance' or 'Time step fraction'");
    // The trapezoidal contact force of 'newmark' and 'generalized alpha' is
    // not stable for a stiff contact: the energy can grow without bound,
    // and epsilon with it.
    if (!(energy_growth <= integrator.energy_error_tolerance()))
      fail("energy growth",
           "the total energy grew by " + approximately(energy_growth) +
             " of the initial energy, more than 'Energy tolerance' = " +
             approximately(integrator.energy_error_tolerance()) +
             " (the scheme is unstable for this contact); use 'Scheme' = "
             "energy conserving or lower 'Time step fraction'");
    // The quasistatic 1-DOF model (log law) is no good reference for the
    // exponential wall, nor beyond the log law's range (NaN).
    if (parameters.contact.law_kind() == WallLawKind::exponential)
      return;
    for (const auto &[name, fe, one_dof] :
         std::vector<std::tuple<std::string, double, double>>{
           {"contact time", summary.contact_time, summary.one_dof_contact_time},
           {"delta_max", summary.delta_max, summary.one_dof_delta_max}})
      if (std::isfinite(one_dof) &&
          !(fe >= 0.5 * one_dof && fe <= 2. * one_dof))
        fail(name + " within a factor 2 of the 1-DOF model",
             approximately(fe, 4) + " against " + approximately(one_dof, 4) +
               " (units R/c and R); " + likely_causes);
  }

  void
  ImpactSimulation::write_outputs() const
  {
    const std::string &directory = parameters.run.output_directory;
    CsvTable           modes({"rank"});
    if (projection)
      modes = projection->table(u, v, energy_initial, factor);
    const auto final_u = gather_on_root(u, communicator),
               final_v = gather_on_root(v, communicator);
    on_root(communicator, [&]() {
      series.write(directory + "/impact.csv");
      write_atomically(directory + "/impact.pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, snapshots);
      });
      if (!revolved_snapshots.empty())
        write_atomically(directory + "/impact_3d.pvd", [&](std::ostream &out) {
          DataOutBase::write_pvd_record(out, revolved_snapshots);
        });
      if (projection)
        modes.write(directory + "/mode_energies.csv");
      write_hdf5(directory + "/impact.h5",
                 summary,
                 series,
                 modes,
                 final_u,
                 final_v,
                 parameters.run.parameters_json,
                 Impact::units(parameters),
                 parameters.units);
    });
  }
} // namespace DiskImpact
