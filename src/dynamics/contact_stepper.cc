#include "dynamics/contact_stepper.h"

#include "contact/complementarity.h"
#include "dynamics/anderson_acceleration.h"

#include <algorithm>

namespace DiskImpact
{
  using namespace dealii;

  template <int dim>
  ContactStepper<dim>::ContactStepper(
    const ElasticityOperator<dim>  &op,
    const ConstraintMap            &constraint_map,
    const InterleavedMass          &mass_product,
    ContactZone                    &zone,
    const TimeIntegrator           &integrator,
    const bool                      exact_constraint,
    std::shared_ptr<Factorization> &factorization,
    const double                    gap_scale,
    MPI_Comm                        communicator)
      : op(op)
      , constraint_map(constraint_map)
      , mass_product(mass_product)
      , zone(zone)
      , integrator(integrator)
      , exact_constraint(exact_constraint)
      , factorization(factorization)
      , gap_scale(gap_scale)
      , communicator(communicator)
  {
    if (exact_constraint && integrator.conserves_energy())
      {
        massless =
          std::make_unique<MasslessZone<dim>>(op, zone.candidate_dofs());
        point_rows        = zone.point_rows();
        static_compliance = massless->compliance(point_rows);
      }
    for (PETScWrappers::MPI::Vector *x :
         std::initializer_list<PETScWrappers::MPI::Vector *>{&u,
                                                             &v,
                                                             &a,
                                                             &u_new,
                                                             &v_new,
                                                             &a_new,
                                                             &b,
                                                             &stiffness_u,
                                                             &mass_u,
                                                             &mass_v,
                                                             &mass_a,
                                                             &mass_u_new,
                                                             &mass_v_new,
                                                             &mass_a_new,
                                                             &work,
                                                             &product})
      *x = op.create_vector();
    u_D.reinit(zone.candidate_dofs().size());
    point_forces.reinit(zone.n_points());
    point_forces_new.reinit(zone.n_points());
  }

  template <int dim>
  void
  ContactStepper<dim>::track_rotation(
    const PETScWrappers::MPI::Vector &field,
    const PETScWrappers::MPI::Vector &momentum)
  {
    rotation_field    = field;
    rotation_momentum = momentum;
    inertia           = momentum * field;
  }

  template <int dim>
  void
  ContactStepper<dim>::enable_plasticity(PlasticStrainField<dim> &field)
  {
    plasticity          = &field;
    plastic_force       = op.create_vector();
    trial_plastic_force = op.create_vector();
    if (integrator.plastic_newton())
      tangent.reinit(op.stiffness_matrix());
  }

  template <int dim>
  Vector<double>
  ContactStepper<dim>::on_contact(const Vector<double> &values_on_D,
                                  const double          angle) const
  {
    Vector<double> values = zone.restrict_to_active(values_on_D);
    if (!zone.tracks_rotation())
      return values;
    Vector<double> with_angle(values.size() + 1);
    for (unsigned int i = 0; i < values.size(); ++i)
      with_angle[i] = values[i];
    with_angle[values.size()] = angle;
    return with_angle;
  }

  template <int dim>
  void
  ContactStepper<dim>::start(const PETScWrappers::MPI::Vector &velocity,
                             const double                      step)
  {
    v = velocity;
    constraint_map.zeroed(v, work);
    op.mass_matrix().vmult(mass_v, work);
    factorize(step);
  }

  template <int dim>
  void
  ContactStepper<dim>::factorize(const double step)
  {
    dt = step;
    // The old solvers' columns belong to the old factorizations (the
    // tangent's was for the old step too).
    retire(solver);
    retire(tangent_solver);
    solver = factorized_solver(op.stiffness_matrix(), factorization);
    solver->add_dofs(zone.active_dofs());
    current = solver.get();
  }

  template <int dim>
  std::unique_ptr<CondensedSolver>
  ContactStepper<dim>::factorized_solver(
    const PETScWrappers::MPI::SparseMatrix &stiffness,
    std::shared_ptr<Factorization>         &into) const
  {
    // A = cK K + cM M (+ cD D): M's pattern is a subset of K's, D's is K's.
    MatrixSum A{{integrator.stiffness_coefficient(), &stiffness},
                {integrator.mass_coefficient(dt), &op.mass_matrix()}};
    if (op.has_damping())
      A.push_back({integrator.damping_coefficient(dt),
                   &op.damping_matrix(),
                   SAME_NONZERO_PATTERN});
    if (into)
      into->refactorize(A);
    else
      into = std::make_shared<Factorization>(
        A,
        communicator,
        op.get_dof_handler().get_fe().n_components(),
        dim == 3);
    auto made = std::make_unique<CondensedSolver>(into,
                                                  op.locally_owned_dofs(),
                                                  communicator);
    made->set_observed_dofs(zone.candidate_dofs());
    return made;
  }

  template <int dim>
  void
  ContactStepper<dim>::retire(std::unique_ptr<CondensedSolver> &retired)
  {
    if (!retired)
      return;
    factorizations_before += retired->n_factorizations();
    solves_before += retired->n_triangular_solves();
    solve_time_before += retired->triangular_solve_time();
    if (current == retired.get())
      current = nullptr;
    retired.reset();
  }

  template <int dim>
  void
  ContactStepper<dim>::use_solver(CondensedSolver &next)
  {
    // Both solvers append the zone's DoFs in the order the zone activates
    // them, so C of the one behind is a prefix of the zone's.
    const auto        &active = zone.active_dofs();
    const unsigned int n      = next.n_contact_dofs();
    if (n < active.size())
      next.add_dofs(
        std::vector<unsigned int>(active.begin() + n, active.end()));
    current = &next;
  }

  template <int dim>
  bool
  ContactStepper<dim>::on_tangent() const
  {
    return tangent_solver && current == tangent_solver.get();
  }

  template <int dim>
  typename ContactStepper<dim>::StepResult
  ContactStepper<dim>::advance(const double step)
  {
    StepResult result;
    if (step != dt)
      factorize(step);
    while (!attempt_step())
      {
        if (++cuts > integrator.max_step_cuts())
          {
            result.converged = false;
            return result;
          }
        ++result.cuts;
        factorize(0.5 * dt);
      }
    complete_step();
    if (plasticity)
      {
        result.plastic_work    = plasticity->accept();
        previous_plastic_force = plastic_force;
        plastic_force          = trial_plastic_force;
      }
    // Friction: each point's traction and slip at the step's end.
    if (zone.has_friction())
      zone.accept_step(on_contact(u_D, theta),
                       on_contact(u1_D_new, theta_new),
                       integrator.contact_average(),
                       integrator.contact_new_weight());
    if (zone.tracks_rotation())
      theta = (rotation_momentum * u_new) / inertia;
    if (op.has_damping())
      {
        integrator.damping_velocity<PETScWrappers::MPI::Vector>(v, v_new, work);
        result.viscous_work = 2. * dt * damping_form(work);
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
    result.dt    = dt;
    result.state = state;
    return result;
  }

  template <int dim>
  void
  ContactStepper<dim>::complete_step()
  {
    // v_new and a_new are linear combinations of fields that satisfy the
    // (homogeneous) constraints, so they satisfy them too.
    integrator.update<PETScWrappers::MPI::Vector>(
      u, u_new, v, a, dt, v_new, a_new);
    constraint_map.zeroed(u_new, work);
    mass_product.vmult(mass_u_new, work);
    integrator.update<PETScWrappers::MPI::Vector>(
      mass_u, mass_u_new, mass_v, mass_a, dt, mass_v_new, mass_a_new);
    update_stiffness_image();
  }

  template <int dim>
  bool
  ContactStepper<dim>::attempt_step()
  {
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
    return plasticity ? attempt_plastic_step() : attempt_contact_step();
  }

  template <int dim>
  bool
  ContactStepper<dim>::attempt_plastic_step()
  {
    // u1 solves A u1 = base + cK f_p(u1) (+ the contact); an iterate solves
    // it with the load x for f_p(u1): one solve and a contact solve. On the
    // tangent A + cK T, x = f_p(u_k) + T u_k. Either way x_{k+1} - x_k is
    // the residual of u_{k+1} over cK. (Perfect plasticity makes the
    // elastic fixed point slow to contract: a deep history.)
    const PETScWrappers::MPI::Vector base = b;
    const double                     cK   = integrator.stiffness_coefficient();
    PETScWrappers::MPI::Vector       product_T;
    // The load of the linearization at @p at with f_p(at) = @p force:
    // force + T at on the tangent, force itself on the elastic matrix.
    const auto linearized_load = [&](const PETScWrappers::MPI::Vector &force,
                                     const PETScWrappers::MPI::Vector &at) {
      PETScWrappers::MPI::Vector load = force;
      if (on_tangent())
        {
          plastic_tangent_product(at, product_T);
          load += product_T;
        }
      return load;
    };
    // Newton from the step's start, or f_p extrapolated linearly from the
    // last two steps.
    PETScWrappers::MPI::Vector x = linearized_load(plastic_force, u);
    if (!on_tangent() && previous_plastic_force.size() == x.size())
      x.sadd(2., -1., previous_plastic_force);
    // The size the tolerance is relative to: f_p's guess (on the tangent,
    // f_p(u_k) of the linearization).
    double guess_norm = plastic_force.l2_norm();
    AndersonAcceleration<PETScWrappers::MPI::Vector> acceleration(15);
    for (unsigned int k = 1;; ++k)
      {
        b = base;
        b.add(cK, x);
        if (!attempt_contact_step())
          return false;
        // The return mapping: on all cells first, then on the cells near
        // yield; a step ends with one on all cells.
        plasticity->evaluate(u_new, trial_plastic_force, k == 1);
        if (on_tangent())
          plastic_tangent_product(u_new, product_T);
        const auto residual = [&]() {
          PETScWrappers::MPI::Vector change = trial_plastic_force;
          if (on_tangent())
            change += product_T;
          change -= x;
          return change;
        };
        PETScWrappers::MPI::Vector change = residual();
        if (!on_tangent())
          guess_norm = x.l2_norm();
        const auto converged = [&]() {
          return change.l2_norm() <=
                 integrator.plastic_tolerance() *
                   std::max(trial_plastic_force.l2_norm(), guess_norm);
        };
        if (k > 1 && converged())
          {
            plasticity->evaluate(u_new, trial_plastic_force, true);
            change = residual();
          }
        if (converged())
          {
            plastic_iterations += k;
            return true;
          }
        if (k == integrator.max_plastic_iterations())
          return false;
        guess_norm = trial_plastic_force.l2_norm();
        // Leave the tangent when no point yields (unloading), or when
        // Newton still fails after a fresh tangent: the yield set then
        // flips between iterates (points at the plastic zone's border
        // loading and unloading) and Newton cycles; the elastic fixed
        // point converges.
        const bool leave_tangent =
          on_tangent() &&
          (plasticity->n_yielding_points() == 0 || k == 2 * newton_stall);
        if (tangent_is_stale(k) || leave_tangent)
          {
            // Linearize at u_k afresh: the history belongs to the old map.
            if (leave_tangent)
              use_solver(*solver);
            else
              refresh_tangent(u_new);
            x            = linearized_load(trial_plastic_force, u_new);
            acceleration = AndersonAcceleration<PETScWrappers::MPI::Vector>(15);
            continue;
          }
        x = acceleration.next(x, change);
      }
  }

  template <int dim>
  bool
  ContactStepper<dim>::tangent_is_stale(const unsigned int k) const
  {
    if (!integrator.plastic_newton() || plasticity->n_yielding_points() == 0 ||
        k >= 2 * newton_stall)
      return false;
    if (!on_tangent())
      return true;
    // The zone's change shows after the first iterate of a step; a stall
    // (several iterates without convergence) means the tangent is off.
    return (k == 1 && plasticity->n_changed_since_tangent() > 0) ||
           k == newton_stall;
  }

  template <int dim>
  void
  ContactStepper<dim>::refresh_tangent(const PETScWrappers::MPI::Vector &at)
  {
    tangent.copy_from(op.stiffness_matrix());
    plasticity->evaluate(at, trial_plastic_force, true, &tangent);
    if (plasticity->n_yielding_points() == 0)
      {
        use_solver(*solver);
        return;
      }
    retire(tangent_solver);
    tangent_solver = factorized_solver(tangent, tangent_factorization);
    ++tangent_factorizations;
    use_solver(*tangent_solver);
  }

  template <int dim>
  void
  ContactStepper<dim>::plastic_tangent_product(
    const PETScWrappers::MPI::Vector &x,
    PETScWrappers::MPI::Vector       &Tx) const
  {
    if (Tx.size() != x.size())
      Tx = op.create_vector();
    constraint_map.zeroed(x, work);
    tangent.vmult(Tx, work);
    op.stiffness_matrix().vmult(product, work);
    Tx -= product;
  }

  template <int dim>
  bool
  ContactStepper<dim>::attempt_contact_step()
  {
    // The response without contact force y: one solve with the factorized
    // matrix, into u_new. The end state is y + X P(u1_C): a dense system
    // on C.
    current->solve(b, u_new);
    // The candidates' DoFs are unconstrained (ConstrainedRow), so y needs
    // its constraints distributed only as part of the end state below.
    const Vector<double> y_D = current->observe(u_new);
    return exact_constraint ? attempt_exact_constraint_step(y_D) :
                              attempt_penalty_step(y_D);
  }

  template <int dim>
  bool
  ContactStepper<dim>::attempt_exact_constraint_step(const Vector<double> &y_D)
  {
    // The trapezoidal step, then (energy conserving) the exact mean along
    // the step: the DoFs with mass see the mean point forces instead of
    // (mu0 + mu1) / 2. Their difference dmu, held by the massless zone,
    // moves the end state by A^{-1} (-K_IM e) = X B^T dmu - 2 e,
    // e = K_MM^{-1} B^T dmu (the massless rows of A are K / 2): no further
    // solve with A.
    Vector<double>       u1_D = y_D;
    Vector<double>       P;
    Vector<double>       applied(zone.n_points());
    Vector<double>       y_D_corrected = y_D;
    AndersonAcceleration<> acceleration(5);
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
        const auto missing = zone.inactive_dofs_of(applied);
        zone.activate(missing);
        current->add_dofs(missing);
        y_D_corrected = y_D;
        y_D_corrected +=
          current->observed_response(zone.constraint_force(applied));
        y_D_corrected.add(-2.,
                          massless->response_on_candidates(point_rows,
                                                           applied));
      }
    if (applied.linfty_norm() > 0.)
      {
        current->add_columns(zone.constraint_force(applied), u_new);
        massless->add_response(point_rows, applied, -2., u_new);
      }
    if (P.size() > 0)
      current->add_columns(P, u_new);
    constraint_map.distribute(u_new);
    state = zone.constraint_state(point_forces,
                                  point_forces_new,
                                  zone.restrict_to_active(u1_D),
                                  integrator.contact_new_weight());
    // The mean force's share beyond the trapezoidal one.
    for (const double dmu : applied)
      state.force_average += dmu;
    u1_D_new = u1_D;
    return true;
  }

  template <int dim>
  bool
  ContactStepper<dim>::attempt_penalty_step(const Vector<double> &y_D)
  {
    // With the rotation tracked, theta is one more unknown: theta1 =
    // theta_y + (w_C . P + Q) / (c_M I), and Q moves u by Q w / (c_M I).
    const bool turning = zone.tracks_rotation();
    double     theta_y = 0., scale = 0.;
    if (turning)
      {
        if (rotation_on_D.size() == 0)
          rotation_on_D = current->observe(rotation_field);
        theta_y = (rotation_momentum * u_new) / inertia;
        scale   = 1. / (integrator.mass_coefficient(dt) * inertia);
      }
    Vector<double> u1_D = y_D;
    Vector<double> P;
    double         Q = 0.;
    theta_new        = theta_y;
    for (;;)
      {
        // Points that touch at the start, the contact-free end or the end
        // found so far take part: their DoFs join C (one solve each).
        const auto missing = zone.dofs_to_activate({&u_D, &y_D, &u1_D});
        zone.activate(missing);
        current->add_dofs(missing);
        if (zone.n_active_dofs() == 0)
          break;
        const unsigned int   n    = zone.n_active_dofs();
        const Vector<double> u0_C = on_contact(u_D, theta);
        const Vector<double> y_C  = on_contact(y_D, theta_y);
        Vector<double>       u1_C = y_C;
        unsigned int         iterations;
        const auto           force = [&](const Vector<double> &u_C) {
          auto f = zone.step_force(u0_C,
                                   u_C,
                                   integrator.contact_average(),
                                   integrator.contact_new_weight(),
                                   true);
          return std::make_pair(f.force, f.jacobian);
        };
        Vector<double>     w_C;
        FullMatrix<double> S;
        if (turning)
          {
            w_C = zone.restrict_to_active(rotation_on_D);
            // S on C bordered by theta's row and column.
            S.reinit(n + 1, n + 1);
            S.fill(current->condensed_matrix());
            for (unsigned int i = 0; i < n; ++i)
              S(i, n) = S(n, i) = scale * w_C[i];
            S(n, n) = scale;
          }
        // Friction's stick-slip kinks shorten Newton's steps: ten times the
        // iterations.
        const unsigned int max_iterations =
          integrator.max_newton_iterations() * (zone.has_friction() ? 10 : 1);
        const bool converged =
          turning ?
            CondensedSolver::solve_condensed(S,
                                             y_C,
                                             force,
                                             integrator.newton_tolerance() *
                                               gap_scale,
                                             max_iterations,
                                             u1_C,
                                             iterations,
                                             true) :
            current->solve_condensed(y_C,
                                     force,
                                     integrator.newton_tolerance() * gap_scale,
                                     max_iterations,
                                     u1_C,
                                     iterations,
                                     zone.has_friction());
        if (!converged)
          return false;
        newton_iterations += iterations;
        P = force(u1_C).first;
        if (turning)
          {
            Q = P[n];
            Vector<double> on_C(n);
            for (unsigned int i = 0; i < n; ++i)
              on_C[i] = P[i];
            P.swap(on_C);
            theta_new = theta_y + scale * (w_C * P + Q);
          }
        u1_D = y_D;
        u1_D += current->observed_response(P);
        if (turning)
          u1_D.add(scale * Q, rotation_on_D);
        if (zone.dofs_to_activate({&u1_D}).empty())
          break;
      }
    if (P.size() > 0)
      current->add_columns(P, u_new);
    if (Q != 0.)
      u_new.add(scale * Q, rotation_field);
    constraint_map.distribute(u_new);
    contact_force = P;
    state         = zone
              .step_force(on_contact(u_D, theta),
                          on_contact(u1_D, theta_new),
                          integrator.contact_average(),
                          integrator.contact_new_weight(),
                          false)
              .state;
    u1_D_new = u1_D;
    return true;
  }

  template <int dim>
  bool
  ContactStepper<dim>::attempt_constrained_step(const Vector<double> &y_D,
                                                Vector<double>       &u1_D,
                                                Vector<double>       &P)
  {
    // The contact DoFs carry no mass: at each step's end they are in
    // equilibrium with the point forces mu1 there, so the step force is
    // P = af F(mu0) + (1 - af) F(mu1), the end state u1 = y + X P and its
    // gaps g = q + W mu1 with W = (1 - af) B S B^T: a complementarity
    // problem on the points that can touch (docs/theory/impact-method.md).
    const double new_weight = integrator.contact_new_weight();
    for (;;)
      {
        const auto missing = zone.dofs_to_activate({&u_D, &y_D, &u1_D});
        zone.activate(missing);
        current->add_dofs(missing);
        point_forces_new.reinit(zone.n_points());
        if (zone.n_active_dofs() == 0)
          return true;
        const Vector<double> F0 = zone.constraint_force(point_forces);
        Vector<double> base_C   = zone.restrict_to_active(y_D); // y_C + af S F0
        Vector<double> s_f0(F0.size());
        current->condensed_matrix().vmult(s_f0, F0);
        base_C.add(1. - new_weight, s_f0);
        const auto system = zone.constraint_system(base_C);
        // W = (1 - af) B S B^T.
        const unsigned int n = system.points.size();
        FullMatrix<double> sbt(current->n_contact_dofs(), n), W(n, n);
        current->condensed_matrix().mTmult(sbt, system.rows);
        system.rows.mmult(W, sbt);
        W *= new_weight;
        std::vector<bool> warm(n);
        for (unsigned int r = 0; r < n; ++r)
          warm[r] = point_forces[system.points[r]] > 0.;
        const auto solution = solve_complementarity(
          W, system.gaps, integrator.newton_tolerance() * gap_scale, warm);
        if (!solution.converged)
          return false;
        newton_iterations += solution.iterations;
        for (unsigned int r = 0; r < n; ++r)
          point_forces_new[system.points[r]] = solution.force[r];
        P = F0;
        P *= 1. - new_weight;
        P.add(new_weight, zone.constraint_force(point_forces_new));
        u1_D = y_D;
        u1_D += current->observed_response(P);
        if (zone.dofs_to_activate({&u1_D}).empty())
          return true;
      }
  }

  template <int dim>
  Vector<double>
  ContactStepper<dim>::mean_force_correction(
    const Vector<double> &u1_D,
    const Vector<double> &applied) const
  {
    // Along the step the DoFs with mass move on a straight line, so the
    // massless zone's gaps without contact forces, q = g - W_s mu, are
    // linear in s from the start to the end state; the forces mu(s) solve
    // the static complementarity problem with them. AVF: the step force is
    // their mean, where the trapezoidal step used (mu0 + mu1) / 2.
    const unsigned int n  = zone.n_points();
    Vector<double>     q0 = zone.point_gaps(u_D), q1 = zone.point_gaps(u1_D);
    Vector<double>     response(n);
    static_compliance.vmult(response, point_forces);
    q0 -= response;
    static_compliance.vmult(response, point_forces_new);
    q1 -= response;
    const Vector<double> target = mean_along_segment(
      static_compliance, q0, q1, integrator.newton_tolerance() * gap_scale);
    Vector<double> change(target);
    change.add(-0.5, point_forces, -0.5, point_forces_new);
    change -= applied;
    const double scale =
      std::max(point_forces.linfty_norm(), point_forces_new.linfty_norm());
    if (change.linfty_norm() <= 1e-12 * scale)
      change = 0.;
    return change;
  }

  template <int dim>
  void
  ContactStepper<dim>::update_stiffness_image()
  {
    if (op.has_damping() || exact_constraint || zone.tracks_rotation() ||
        on_tangent())
      {
        // K u_new with u_new's constrained entries zeroed.
        constraint_map.zeroed(u_new, work);
        op.stiffness_matrix().vmult(stiffness_u, work);
      }
    else
      {
        // The step solved A u1 = b + E_C P with A = cK K + cM M (not the
        // tangent's), so in the
        // unconstrained rows K u1 = (b + E_C P - cM M u1) / cK: no product
        // with K. (The constrained rows, which differ, are zeroed in u where
        // it meets them and kept to themselves by the solve.)
        stiffness_u = b;
        if (contact_force.size() > 0)
          current->add_forces(contact_force, stiffness_u);
        stiffness_u.add(-integrator.mass_coefficient(dt), mass_u_new);
        stiffness_u /= integrator.stiffness_coefficient();
      }
    if (plasticity)
      stiffness_u -= trial_plastic_force;
  }

  template <int dim>
  double
  ContactStepper<dim>::damping_form(const PETScWrappers::MPI::Vector &x) const
  {
    constraint_map.zeroed(x, work);
    op.damping_matrix().vmult(product, work);
    return 0.5 * (work * product);
  }

  template <int dim>
  void
  ContactStepper<dim>::refactorize()
  {
    factorize(dt);
    // K u of the current state with the new K.
    constraint_map.zeroed(u, work);
    op.stiffness_matrix().vmult(stiffness_u, work);
    if (plasticity)
      stiffness_u -= plastic_force;
  }

  template <int dim>
  double
  ContactStepper<dim>::strain_energy() const
  {
    constraint_map.zeroed(u, work);
    double energy = 0.5 * (work * stiffness_u);
    if (plasticity)
      energy +=
        plasticity->plastic_strain_energy() - 0.5 * (work * plastic_force);
    return energy;
  }

  template <int dim>
  const PETScWrappers::MPI::Vector &
  ContactStepper<dim>::current_plastic_force() const
  {
    return plastic_force;
  }

  template <int dim>
  unsigned int
  ContactStepper<dim>::n_plastic_iterations() const
  {
    return plastic_iterations;
  }

  template <int dim>
  unsigned int
  ContactStepper<dim>::n_tangent_factorizations() const
  {
    return tangent_factorizations;
  }

  template <int dim>
  double
  ContactStepper<dim>::time() const
  {
    return t;
  }

  template <int dim>
  const StateVector &
  ContactStepper<dim>::displacement() const
  {
    return u;
  }

  template <int dim>
  const StateVector &
  ContactStepper<dim>::velocity() const
  {
    return v;
  }

  template <int dim>
  const PETScWrappers::MPI::Vector &
  ContactStepper<dim>::mass_times_velocity() const
  {
    return mass_v;
  }

  template <int dim>
  const PETScWrappers::MPI::Vector &
  ContactStepper<dim>::stiffness_times_displacement() const
  {
    return stiffness_u;
  }

  template <int dim>
  unsigned int
  ContactStepper<dim>::n_newton_iterations() const
  {
    return newton_iterations;
  }

  template <int dim>
  unsigned int
  ContactStepper<dim>::n_factorizations() const
  {
    return factorizations_before + solver->n_factorizations() +
           (tangent_solver ? tangent_solver->n_factorizations() : 0);
  }

  template <int dim>
  unsigned int
  ContactStepper<dim>::n_triangular_solves() const
  {
    return solves_before + solver->n_triangular_solves() +
           (tangent_solver ? tangent_solver->n_triangular_solves() : 0);
  }

  template <int dim>
  double
  ContactStepper<dim>::triangular_solve_time() const
  {
    return (solve_time_before + solver->triangular_solve_time() +
            (tangent_solver ? tangent_solver->triangular_solve_time() : 0.)) /
           n_triangular_solves();
  }

  template <int dim>
  Vector<double>
  ContactStepper<dim>::contact_force_on_candidates() const
  {
    Vector<double>       on_D(zone.candidate_dofs().size());
    const Vector<double> on_C =
      exact_constraint ? zone.constraint_force(point_forces) : contact_force;
    const auto &active = zone.active_dofs();
    for (unsigned int k = 0; k < on_C.size() && k < active.size(); ++k)
      on_D[active[k]] = on_C[k];
    return on_D;
  }

  template <int dim>
  unsigned int
  ContactStepper<dim>::n_contact_dofs() const
  {
    return current->n_contact_dofs();
  }

  template class ContactStepper<2>;
  template class ContactStepper<3>;
} // namespace DiskImpact
