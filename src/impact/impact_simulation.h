#pragma once

#include "contact/contact_operator.h"
#include "contact/contact_zone.h"
#include "dynamics/contact_stepper.h"
#include "elasticity/body_motion.h"
#include "elasticity/constraint_map.h"
#include "elasticity/elasticity_operator.h"
#include "impact/impact_operators.h"
#include "impact/impact_summary.h"
#include "modal/modal_projection.h"
#include "output/contact_traction.h"
#include "output/csv_table.h"

#include <deal.II/lac/petsc_vector.h>

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /**
   * One impact (task 'impact', docs/theory/impact-method.md): the 1-DOF
   * estimate of the collision, the mesh graded toward the contact, the
   * operators, time stepping with the contact condensed on its DoFs
   * (CondensedSolver), the end of the collision (the step-mean contact
   * force back at zero, Schwager & Pöschel 2007) plus a margin, and the
   * outputs. Built and run once; its mesh and operators may be shared with
   * runs that differ only in the time step.
   */
  template <int dim>
  class ImpactSimulation
  {
  public:
    /// With @p operators built for @p parameters (but perhaps another time
    /// step), or null to build them here.
    ImpactSimulation(const Parameters                     &parameters,
                     MPI_Comm                              communicator,
                     bool                                  write_outputs,
                     std::shared_ptr<ImpactOperators<dim>> operators = {});

    ImpactSummary
    run();

  private:
    /// Contact time (for the step) and largest load (for the mesh) from the
    /// 1-DOF log law; beyond its range, Gerl & Zippelius' eq. 61.
    void
    estimate_collision();
    /// The contact zone and the solver's other pieces on the operators,
    /// the modes to project on.
    void
    setup_operators();
    /// Undeformed, moving uniformly toward the wall.
    void
    set_initial_state();
    /// One step of the stepper; a RunError if it cannot be taken.
    void
    advance();
    /// Append the state after a step to the time series.
    void
    record(double time, const ContactState &state);
    /// The largest von Mises stress near the contact in the state of the
    /// largest force (2D models).
    void
    record_stress_peak();
    /// Whether the collision has ended and the margin after it passed.
    bool
    collision_over();
    /// Every 30 s of wall time, in a run that writes its outputs, on the
    /// first rank: the time reached against the contact time expected, the
    /// steps so far and the wall time left at that pace.
    void
    report_progress(std::chrono::steady_clock::time_point start);
    /// ParaView output of the current state.
    void
    snapshot();
    /// Fill the summary's results after the last step.
    void
    finish();
    /// Two bodies: each one's momentum balance and vibration energy.
    void
    finish_pair();
    /// Throw a RunError if the result cannot be right: epsilon outside
    /// [0, 1], the energy balance of an energy-conserving scheme beyond its
    /// tolerance, contact time or delta_max beyond a factor 2 of the 1-DOF
    /// model (locking, a far too coarse mesh or soft penalty).
    void
    check_result() const;
    void
    write_outputs() const;

    /// x^T M x / 2 or x^T K x / 2 (constrained entries ignored).
    double
    quadratic_form(const dealii::PETScWrappers::MPI::SparseMatrix &matrix,
                   const dealii::PETScWrappers::MPI::Vector       &x) const;
    /// The same, keeping the matrix times x (constrained entries zeroed) in
    /// @p matrix_x.
    double
    quadratic_form(const dealii::PETScWrappers::MPI::SparseMatrix &matrix,
                   const dealii::PETScWrappers::MPI::Vector       &x,
                   dealii::PETScWrappers::MPI::Vector &matrix_x) const;
    /// The centre-of-mass component of x along the wall normal.
    double
    mean_along_normal(const dealii::PETScWrappers::MPI::Vector &x) const;
    /// The centre-of-mass component of x along the wall's tangent, and
    /// its rotation about e_z (whole disk).
    double
    mean_along_tangent(const dealii::PETScWrappers::MPI::Vector &x) const;
    double
    mean_rotation(const dealii::PETScWrappers::MPI::Vector &x) const;
    /// The kinetic energy of the body's rigid motion at the velocity @p v:
    /// its centre of mass's and, for a body that turns, its spin's.
    double
    rigid_motion_energy(const dealii::PETScWrappers::MPI::Vector &v) const;
    /// The discrete body's centre of mass (x M-weighted).
    dealii::Point<dim>
    center_of_mass() const;
    /// The tangential velocity and spin before the impact, and the fields
    /// and momenta that measure them.
    void
    set_up_rotation(dealii::PETScWrappers::MPI::Vector &v);
    /// The oblique impact's results: tangential restitution, spin,
    /// rebound angles, impulse balances.
    void
    finish_oblique();
    /// The kinetic energy of the centre of mass (of each body) at the
    /// velocity v, whose relative centre-of-mass velocity is @p v_com.
    double
    translational_energy(double v_com) const;

    const Parameters &parameters;
    MPI_Comm          communicator;
    const bool        with_outputs;
    double            radius;        ///< R
    double            velocity_unit; ///< c
    double            impact_speed;  ///< v_i
    double            body_mass;     ///< the whole body's mass
    /// The whole body's loads over the computed domain's: 2 on a half
    /// disk, 1 on a whole disk or a sphere (its meridian's integrals are
    /// over the whole sphere).
    double domain_factor;
    double force_unit; ///< E2 R (disk, per unit thickness) or E2 R^2

    ImpactSummary summary;
    double        contact_time_estimate = 0.;
    double        approach_estimate     = 0.; ///< largest approach, 1-DOF
    /// When report_progress() last printed (or the time loop began).
    std::chrono::steady_clock::time_point last_report;

    /// The mesh and operators, perhaps shared with other runs.
    std::shared_ptr<ImpactOperators<dim>> operators;
    ElasticityOperator<dim>              &op;
    /// op's constraints as a matrix, for the time loop.
    const ConstraintMap         &constraint_map;
    std::unique_ptr<ContactZone> zone;
    /// Two bodies (a deformable partner): their centre-of-mass motion.
    std::unique_ptr<BodyMotion<dim>>     bodies;
    std::unique_ptr<ModalProjection>     projection;
    std::unique_ptr<ContactStepper<dim>> stepper;
    /// The plastic strain of an elastic-plastic body (null if elastic).
    std::unique_ptr<PlasticStrainField<dim>> plasticity;
    /// The outputs' contact traction (made at the first snapshot).
    std::unique_ptr<ContactTraction<dim>> traction_field;

    /// The centre of mass's motion along the wall normal: the uniform field
    /// n, its momentum functional M n and the mass n . M n.
    dealii::PETScWrappers::MPI::Vector         along_normal, normal_momentum;
    double                                     normal_mass = 0.;
    /// A whole disk: its motion along the wall's tangent t and its rotation
    /// about e_z through its centre (the fields t and e_z x (x - c), their
    /// momentum functionals, mass and moment of inertia).
    bool                               tracks_rotation = false;
    dealii::Point<dim>                 rotation_center;
    dealii::PETScWrappers::MPI::Vector tangent_momentum, rotation_momentum;
    /// The displacement and the contact's half-width at the largest force.
    dealii::PETScWrappers::MPI::Vector largest_force_displacement;
    double                             largest_force_half_width = 0.;
    double                             tangent_mass = 0., inertia = 0.;
    double v_tangent_initial = 0., spin_initial = 0.;
    /// The wall's tangential and angular impulses so far, and the energy
    /// friction dissipated.
    double tangential_impulse = 0., angular_impulse = 0., friction_work = 0.;
    mutable dealii::PETScWrappers::MPI::Vector work, product;
    double                                     energy_initial = 0.;
    double                                     v_com_initial  = 0.;

    double dt      = 0.;
    double impulse = 0., energy_error = 0.;
    /// max (E(t) - E(0)) / E(0): no scheme may create energy.
    double energy_growth = 0.;
    /// Energy dissipated by the viscosity so far (whole disk).
    double       dissipated = 0.;
    /// Plastic work so far (whole body).
    double       plastic_work = 0.;
    ContactState state;
    /// The end of contact (-1: not yet) and the last two positive step-mean
    /// forces with their mid-step times.
    double contact_end    = -1.;
    double previous_force = 0., previous_time = 0.;
    double older_force = 0., older_time = -1.;

    CsvTable                                    series;
    std::vector<std::pair<double, std::string>> snapshots;
    std::vector<std::pair<double, std::string>> revolved_snapshots;
  };

  /// One impact of @p parameters (ImpactSimulation of the geometry's
  /// dimension); with @p operators, on those (built for @p parameters but
  /// perhaps another time step) instead of its own.
  ImpactSummary
  run_impact(const Parameters                    &parameters,
             MPI_Comm                             communicator,
             bool                                 write_time_series = true,
             std::shared_ptr<ImpactOperatorsBase> operators         = {});
} // namespace DiskImpact
