#pragma once

#include "contact/contact.h"
#include "contact/contact_zone.h"
#include "dynamics/condensed_solver.h"
#include "dynamics/factorization.h"
#include "dynamics/massless_zone.h"
#include "dynamics/state_vector.h"
#include "dynamics/time_integrator.h"
#include "elasticity/constraint_map.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/interleaved_mass.h"
#include "elasticity/plastic_strain_field.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <utility>
#include <vector>

namespace DiskImpact
{
  /**
   * The time step of elastic bodies in contact (docs/theory/impact-method.md):
   * the integrator's effective matrix factorized once per step size, the
   * response without contact force by one solve, and the contact solved on
   * the few DoFs it acts on (CondensedSolver): by Newton's method for a
   * penalty-type law, by a complementarity problem for the exact
   * constraint (with the energy-conserving scheme, the exact mean of the
   * point forces along the step by Anderson-accelerated fixed point). A
   * step whose contact solve fails is halved and refactorized.
   *
   * Built from the elasticity operator (with its constraints as a matrix
   * and its mass product), the contact zone (with its law) and the
   * integrator; @p exact_constraint chooses the solver of the exact
   * constraint g >= 0 (ContactZone without a law). It knows nothing of the task
   * that drives it. Times and lengths are in the operator's units.
   */
  template <int dim>
  class ContactStepper
  {
  public:
    /// What one call of advance() did.
    struct StepResult
    {
      /// False if the contact solve failed and the steps of this stepper
      /// have been halved 'Maximum step cuts' times already; the state is
      /// then unchanged.
      bool converged = true;
      /// The step taken (the one asked for, halved by each cut).
      double dt = 0.;
      /// Halvings in this call.
      unsigned int cuts = 0;
      /// The contact at the step's end; force_average is the step's mean
      /// force (its impulse / dt).
      ContactState state;
      /// The viscous work of the step, dt v^T D v at the damping's
      /// velocity (zero without damping).
      double viscous_work = 0.;
      /// The plastic work of the step (enable_plasticity(), else zero).
      double plastic_work = 0.;
    };

    /**
     * @p factorization: where the effective matrix's factorization is kept,
     * perhaps made by an earlier stepper on the same operators (it is then
     * refactorized, keeping its pattern's part). @p gap_scale: the length
     * the contact solve's 'Newton tolerance' is relative to (the largest
     * approach expected). Collective.
     */
    ContactStepper(const ElasticityOperator<dim>  &op,
                   const ConstraintMap            &constraint_map,
                   const InterleavedMass          &mass_product,
                   ContactZone                    &zone,
                   const TimeIntegrator           &integrator,
                   bool                            exact_constraint,
                   std::shared_ptr<Factorization> &factorization,
                   double                          gap_scale,
                   MPI_Comm                        communicator);

    /**
     * Track the body's rigid rotation theta = m . u / (m . w) for the zone
     * (ContactZone::enable_rotation()): @p rotation_field w = e_z x (x - c),
     * @p rotation_momentum m = M w. The contact's generalized force Q on
     * theta acts as the body force Q M w / (m . w), whose response to the
     * effective matrix is Q w / (c_M m . w) (K w = 0): one more unknown in
     * the condensed solve, no more solves. Call before start().
     */
    void
    track_rotation(const dealii::PETScWrappers::MPI::Vector &rotation_field,
                   const dealii::PETScWrappers::MPI::Vector &rotation_momentum);

    /**
     * An elastic-plastic body: the internal force is K u - f_p with the
     * plastic strain's force f_p of @p field. Each step iterates on the
     * load x of its end state u1 (the step's solve with the load
     * (1 - af) x, and a contact solve), x_{k+1} - x_k being the step's
     * residual, with Anderson's acceleration to 'Plastic tolerance':
     * - with the elastic factorization (no point yields, or 'Plastic
     *   solver' = fixed point), x is f_p's guess, from f_p extrapolated
     *   from the last two steps;
     * - while points yield ('Plastic solver' = Newton), the effective
     *   matrix holds K + T, T the consistent plastic tangent at some state
     *   (PlasticStrainField::evaluate()), and x = f_p(u_k) + T u_k: Newton's
     *   linearization at the last iterate. K + T is assembled and
     *   factorized again when the set of yielding points has changed since,
     *   or when an iteration stalls; if Newton stalls again the step goes
     *   on with the elastic factorization.
     * Call before start().
     */
    void
    enable_plasticity(PlasticStrainField<dim> &field);

    /// Start from rest (u = a = 0) with the velocity @p velocity (its
    /// constraints satisfied) and factorize for the step @p dt.
    void
    start(const dealii::PETScWrappers::MPI::Vector &velocity, double dt);

    /// One step of size @p dt (refactorized if it differs from the last),
    /// halved after each failed contact solve (at most 'Maximum step cuts'
    /// halvings in all steps together).
    StepResult
    advance(double dt);

    /// Refactorize the effective matrix from the operator's matrices as
    /// they are now: after a material whose stiffness changes
    /// (ConstitutiveLaw::changes_stiffness()) has had K reassembled.
    /// Collective.
    void
    refactorize();

    /// The time reached.
    double
    time() const;
    const StateVector &
    displacement() const;
    const StateVector &
    velocity() const;
    /// M v and K u of the current state (constrained entries zeroed): the
    /// kinetic and strain energies are v . (M v) / 2 and u . (K u) / 2.
    const dealii::PETScWrappers::MPI::Vector &
    mass_times_velocity() const;
    const dealii::PETScWrappers::MPI::Vector &
    stiffness_times_displacement() const;
    /// The elastic strain energy of the current state: u . (K u) / 2, less
    /// u . f_p and plus int eps_p : C : eps_p dV / 2 for an elastic-plastic
    /// body (its elastic strain's energy).
    double
    strain_energy() const;
    /// An elastic-plastic body's f_p at the current state (the internal
    /// force is K u - f_p).
    const dealii::PETScWrappers::MPI::Vector &
    current_plastic_force() const;
    /// Plastic iterations of all steps so far (enable_plasticity()).
    unsigned int
    n_plastic_iterations() const;
    /// Factorizations of the tangent matrix so far (enable_plasticity(),
    /// 'Plastic solver' = Newton); n_factorizations() counts them too.
    unsigned int
    n_tangent_factorizations() const;

    /// Newton (or complementarity) iterations of all steps so far.
    unsigned int
    n_newton_iterations() const;
    /// Factorizations and pairs of triangular solves so far, and their
    /// mean time.
    unsigned int
    n_factorizations() const;
    unsigned int
    n_triangular_solves() const;
    double
    triangular_solve_time() const;
    /// |C|: the contact DoFs the condensed solve holds.
    unsigned int
    n_contact_dofs() const;
    /// The contact's force on the candidates' DoFs (ContactZone::
    /// candidate_dofs()) in the last step: the step force of a penalty-type
    /// law, the end state's point forces of the exact constraint.
    dealii::Vector<double>
    contact_force_on_candidates() const;

  private:
    /// Factorize the effective matrix cm M + cd D + (1 - af) K for @p dt.
    void
    factorize(double dt);
    /// The contact solve of one step from the current state; false if it
    /// fails.
    bool
    attempt_step();
    /// The step's solve with the right-hand side b, then its contact solve.
    bool
    attempt_contact_step();
    /// attempt_step() for an elastic-plastic body: the plastic iteration
    /// around attempt_contact_step().
    bool
    attempt_plastic_step();
    /// Whether the plastic iteration should assemble and factorize the
    /// tangent at its @p k th iterate (not converged): points yield and
    /// the elastic matrix is in use, or the plastic zone has changed since
    /// the tangent's assembly, or the iteration stalls.
    bool
    tangent_is_stale(unsigned int k) const;
    /// Assemble K + T at @p at (the trial states there, their f_p into
    /// trial_plastic_force) and factorize the effective matrix with it for
    /// the solves that follow; the elastic one if no point yields.
    void
    refresh_tangent(const dealii::PETScWrappers::MPI::Vector &at);
    /// Solve with @p next from now on, its C brought up to the zone's
    /// active DoFs.
    void
    use_solver(CondensedSolver &next);
    /// Whether the solves use the tangent.
    bool
    on_tangent() const;
    /// @p Tx = T x, T the plastic part of the tangent (K + T - K).
    void
    plastic_tangent_product(const dealii::PETScWrappers::MPI::Vector &x,
                            dealii::PETScWrappers::MPI::Vector       &Tx) const;
    /// A solver of cK @p stiffness + cM M (+ cD D) for the step dt, its
    /// factorization made or refactorized in @p into (whose earlier
    /// solvers must be retired), observing the candidates' DoFs; C empty.
    std::unique_ptr<CondensedSolver>
    factorized_solver(const dealii::PETScWrappers::MPI::SparseMatrix &stiffness,
                      std::shared_ptr<Factorization> &into) const;
    /// Count @p retired's factorizations and solves in the totals.
    void
    retire(std::unique_ptr<CondensedSolver> &retired);
    /// attempt_step() for a penalty-type law: Newton on C.
    bool
    attempt_penalty_step(const dealii::Vector<double> &y_D);
    /// attempt_step() for the exact constraint: complementarity on the
    /// points, and the mean point forces of the energy-conserving scheme.
    bool
    attempt_exact_constraint_step(const dealii::Vector<double> &y_D);
    /// The end state's point forces from the complementarity problem on the
    /// active points.
    bool
    attempt_constrained_step(const dealii::Vector<double> &y_D,
                             dealii::Vector<double>       &u1_D,
                             dealii::Vector<double>       &P);
    /// For the end state @p u1_D: the exact mean of the point forces along
    /// the step, less the trapezoidal mean, less the correction
    /// @p applied so far (zero once below rounding).
    dealii::Vector<double>
    mean_force_correction(const dealii::Vector<double> &u1_D,
                          const dealii::Vector<double> &applied) const;
    /// The new state's velocity, acceleration, their mass images and K u.
    void
    complete_step();
    /// K u_new into stiffness_u, from the step's linear system where it
    /// holds, else by a product.
    void
    update_stiffness_image();
    /// x^T D x / 2 (constrained entries ignored).
    double
    damping_form(const dealii::PETScWrappers::MPI::Vector &x) const;

    const ElasticityOperator<dim>  &op;
    const ConstraintMap            &constraint_map;
    const InterleavedMass          &mass_product;
    ContactZone                    &zone;
    const TimeIntegrator           &integrator;
    const bool                      exact_constraint;
    std::shared_ptr<Factorization> &factorization;
    const double                    gap_scale;
    MPI_Comm                        communicator;

    /// The solver with the effective matrix, the one with the tangent's
    /// (enable_plasticity(), Newton) and the one the solves use.
    std::unique_ptr<CondensedSolver> solver, tangent_solver;
    CondensedSolver                 *current = nullptr;
    double                           dt = 0., t = 0.;
    /// The step's results so far (attempt_step()).
    ContactState state;
    unsigned int newton_iterations = 0;
    /// Halvings of the step so far: at most 'Maximum step cuts' in all.
    unsigned int cuts                  = 0;
    unsigned int factorizations_before = 0, solves_before = 0;
    double       solve_time_before = 0.;

    StateVector                        u, v, a, u_new, v_new, a_new;
    dealii::PETScWrappers::MPI::Vector b;
    /// K u of the current state (K u - f_p for an elastic-plastic body):
    /// for the strain energy and the next step's right-hand side.
    dealii::PETScWrappers::MPI::Vector stiffness_u;
    /// enable_plasticity(): the field, f_p of its accepted states, of its
    /// last trial states and of the step before, the plastic iterations so
    /// far.
    PlasticStrainField<dim>           *plasticity = nullptr;
    dealii::PETScWrappers::MPI::Vector plastic_force, trial_plastic_force,
      previous_plastic_force;
    unsigned int plastic_iterations = 0;
    /// Newton: K + T, its effective matrix's factorization (its pattern
    /// kept from one to the next) and their number.
    dealii::PETScWrappers::MPI::SparseMatrix tangent;
    std::shared_ptr<Factorization>           tangent_factorization;
    unsigned int                             tangent_factorizations = 0;
    /// Newton iterates of a step without convergence after which the
    /// tangent is refreshed; after twice as many the step goes on by the
    /// elastic fixed point.
    static constexpr unsigned int newton_stall = 4;
    /// The last step's contact force P on C (laws other than 'constraint').
    dealii::Vector<double> contact_force;
    /// M u, M v, M a (constrained entries zeroed) and their new values:
    /// the Newmark relations are linear, so M v and M a follow from M u
    /// by the same relations, one product with M per step.
    StateVector mass_u, mass_v, mass_a, mass_u_new, mass_v_new, mass_a_new;
    /// u on the contact candidates' DoFs, at the step's start and end.
    dealii::Vector<double> u_D, u1_D_new;
    /// track_rotation(): w, M w, w on D, the moment of inertia m . w, the
    /// rotation theta at the step's start and end.
    dealii::PETScWrappers::MPI::Vector rotation_field, rotation_momentum;
    dealii::Vector<double>             rotation_on_D;
    double inertia = 0., theta = 0., theta_new = 0.;
    /// The values on C of @p values_on_D, with @p angle appended when the
    /// rotation is tracked.
    dealii::Vector<double>
    on_contact(const dealii::Vector<double> &values_on_D, double angle) const;
    /// Law 'constraint': the point forces at the step's start and end.
    dealii::Vector<double> point_forces, point_forces_new;
    /// With the energy-conserving scheme and the exact constraint: the
    /// massless zone in equilibrium and the points' static compliance, for
    /// the exact mean force.
    std::unique_ptr<MasslessZone<dim>>                        massless;
    std::vector<std::vector<std::pair<unsigned int, double>>> point_rows;
    dealii::FullMatrix<double>                                static_compliance;
    mutable dealii::PETScWrappers::MPI::Vector                work, product;
  };
} // namespace DiskImpact
