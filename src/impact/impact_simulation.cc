#include "impact/impact_simulation.h"

#include "base/peak_memory.h"
#include "base/run_error.h"
#include "elasticity/largest_von_mises.h"
#include "elasticity/rotation_field.h"
#include "impact/impact_estimates.h"
#include "impact/impact_mesh.h"
#include "output/atomic_file.h"
#include "output/hdf5_output.h"
#include "output/state_output.h"
#include "run/parameters.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
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
                       "energy_friction",
                       "energy_total",
                       "tangential_force",
                       "v_tangential_com",
                       "spin",
                       "energy_plastic"});
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
      file.write_table("summary", summary_table(summary));
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

  template <int dim>
  ImpactSimulation<dim>::ImpactSimulation(
    const Parameters                     &parameters,
    MPI_Comm                              communicator,
    const bool                            write_outputs,
    std::shared_ptr<ImpactOperators<dim>> operators)
      : parameters(parameters)
      , communicator(communicator)
      , with_outputs(write_outputs)
      , radius(parameters.geometry.radius())
      , velocity_unit(parameters.material.velocity_unit())
      , impact_speed(parameters.impact.normal_velocity() * velocity_unit)
      , body_mass(parameters.material.density() * parameters.geometry.volume())
      , domain_factor(1. / parameters.geometry.domain_share())
      , force_unit(DiskImpact::force_unit(parameters))
      , operators(
          operators ?
            std::move(operators) :
            std::make_shared<ImpactOperators<dim>>(parameters, communicator))
      , op(this->operators->op)
      , constraint_map(*this->operators->constraint_map)
      , series(time_series_table())
  {
    summary.velocity          = parameters.impact.velocity();
    summary.graded_half_width = graded_width(parameters) / radius;
    summary.angle    = parameters.impact.incidence_angle_degrees();
    summary.friction = parameters.contact.friction_coefficient();
    (parameters.geometry.is_sphere() ? summary.ramirez_u :
                                       summary.schwager_alpha) =
      dissipation_parameter(parameters);
  }

  template <int dim>
  ImpactSummary
  ImpactSimulation<dim>::run()
  {
    estimate_collision();
    setup_operators();
    dt = parameters.time_integrator.time_step(contact_time_estimate);
    set_initial_state();
    record(0., ContactState());
    if (parameters.impact.snapshot_interval() > 0)
      snapshot();

    const auto start = std::chrono::steady_clock::now();
    last_report      = start;
    do
      {
        advance();
        record(stepper->time(), state);
        report_progress(start);
        if (projection && state.force_average > 0.)
          projection->add_sample(stepper->displacement(),
                                 stepper->velocity(),
                                 dt);
        if (parameters.impact.snapshot_interval() > 0 &&
            summary.steps % parameters.impact.snapshot_interval() == 0)
          snapshot();
      }
    while (!collision_over());
    summary.wall_time_loop =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    record_stress_peak();
    finish();
    check_result();
    snapshot();
    if (with_outputs)
      write_outputs();
    return summary;
  }

  template <int dim>
  void
  ImpactSimulation<dim>::estimate_collision()
  {
    const auto estimate          = DiskImpact::estimate_collision(parameters);
    contact_time_estimate        = estimate.contact_time;
    approach_estimate            = estimate.largest_compression;
    summary.one_dof_contact_time = estimate.one_dof_contact_time;
    summary.one_dof_delta_max    = estimate.one_dof_delta_max;
    summary.one_dof_epsilon      = estimate.one_dof_epsilon;
    summary.one_dof_epsilon_overlap   = estimate.one_dof_epsilon_overlap;
    summary.one_dof_epsilon_unloading = estimate.one_dof_epsilon_unloading;
  }

  template <int dim>
  void
  ImpactSimulation<dim>::setup_operators()
  {
    const auto &geometry  = parameters.geometry;
    const auto &law       = operators->law;
    const bool  pair      = parameters.partner.is_body();
    summary.massless_dofs = op.n_massless_dofs();
    summary.n_dofs        = op.get_dof_handler().n_dofs();
    // The modes to project on, of the operator the time stepping uses (the
    // plane models').
    if constexpr (dim == 2)
      if (with_outputs && parameters.impact.n_projected_modes() > 0 && !pair)
        projection = std::make_unique<ModalProjection>(
          op,
          geometry,
          std::pow(parameters.material.transverse_wave_speed() / radius, 2),
          parameters.impact.n_projected_modes());
    const RigidWall<dim> wall = parameters.contact.wall<dim>();
    const double         mu   = parameters.contact.friction_coefficient();
    // A whole disk, a whole or half sphere: its tangential motion and spin;
    // a rotation of the body (friction, an initial spin) is taken exactly
    // by the contact, about the discrete body's centre of mass (the body's
    // centre up to the discretization).
    tracks_rotation = geometry.turns_in_plane() && !pair;
    const bool turning =
      tracks_rotation && (mu > 0. || parameters.impact.spin() != 0.);
    rotation_center = turning ? center_of_mass() :
                                embedded<dim>(geometry.center());
    zone            = std::make_unique<ContactZone>(op,
                                         wall,
                                         law,
                                         rotation_center,
                                         operators->candidate_bound,
                                         pair,
                                         dim == 3 && geometry.is_sphere());
    if (mu > 0.)
      zone->enable_friction(mu);
    if (turning)
      zone->enable_rotation();
    stepper                   = std::make_unique<ContactStepper<dim>>(op,
                                                    constraint_map,
                                                    *operators->mass_product,
                                                    *zone,
                                                    parameters.time_integrator,
                                                    !law,
                                                    operators->factorization,
                                                    approach_estimate,
                                                    communicator);
    if (pair)
      bodies = std::make_unique<BodyMotion<dim>>(op, wall.normal, 2);
    const auto materials = ImpactOperatorsBase::materials(parameters);
    if (std::any_of(materials.begin(), materials.end(), [](const auto &m) {
          return m.is_plastic();
        }))
      {
        // Parameters::check_plasticity() refused the exact constraint.
        Assert(law != nullptr, ExcInternalError());
        plasticity = std::make_unique<PlasticStrainField<dim>>(op, materials);
        stepper->enable_plasticity(*plasticity);
      }
  }

  template <int dim>
  void
  ImpactSimulation<dim>::set_initial_state()
  {
    along_normal               = op.create_vector();
    work                       = op.create_vector();
    product                    = op.create_vector();
    auto                v      = op.create_vector();
    const auto          normal = parameters.contact.wall<dim>().normal;
    std::vector<double> components(dim);
    for (unsigned int d = 0; d < dim; ++d)
      components[d] = normal[d];
    VectorTools::interpolate(op.get_mapping(),
                             op.get_dof_handler(),
                             Functions::ConstantFunction<dim>(components),
                             along_normal);
    op.get_constraints().distribute(along_normal);
    if (bodies)
      {
        // The centre-of-mass frame: v1 m1 = v2 m2, v1 + v2 = v_i.
        const double m1 = bodies->mass(0), m2 = bodies->mass(1);
        v.add(-impact_speed * m2 / (m1 + m2), bodies->normal_field(0));
        v.add(impact_speed * m1 / (m1 + m2), bodies->normal_field(1));
      }
    else
      v.add(-impact_speed, along_normal);
    if (tracks_rotation)
      set_up_rotation(v);
    stepper->start(v, dt);
    // The centre of mass's motion along the wall normal is the momentum
    // (M x) . n over the mass n . M n (valid for a redistributed mass too).
    normal_momentum = op.mass_functional(along_normal);
    normal_mass     = normal_momentum * along_normal;
    constraint_map.zeroed(v, work);
    energy_initial =
      domain_factor * 0.5 * (work * stepper->mass_times_velocity());
    v_com_initial = mean_along_normal(v);
  }

  template <int dim>
  double
  ImpactSimulation<dim>::rigid_motion_energy(
    const PETScWrappers::MPI::Vector &v) const
  {
    // The normal, tangential and rotational parts are M-orthogonal (the
    // rotation about the centre of mass); without rotation tracking the
    // tangent mass and the inertia are 0.
    const double v_n = mean_along_normal(v), v_t = mean_along_tangent(v),
                 omega = mean_rotation(v);
    return 0.5 * domain_factor *
           (normal_mass * v_n * v_n + tangent_mass * v_t * v_t +
            inertia * omega * omega);
  }

  template <int dim>
  dealii::Point<dim>
  ImpactSimulation<dim>::center_of_mass() const
  {
    // x_com . e_d = (M e_d) . x / (M e_d) . e_d, the position field x
    // interpolated exactly (it is linear). The whole body's centre lies on
    // the planes of symmetry of the computed part (z = 0 of a half sphere).
    auto position = op.create_vector(), along = op.create_vector();
    VectorTools::interpolate(op.get_mapping(),
                             op.get_dof_handler(),
                             Functions::IdentityFunction<dim>(),
                             position);
    dealii::Point<dim> center;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<double> unit(dim, 0.);
        unit[d] = 1.;
        VectorTools::interpolate(op.get_mapping(),
                                 op.get_dof_handler(),
                                 Functions::ConstantFunction<dim>(unit),
                                 along);
        const auto momentum = op.mass_functional(along);
        const bool mirrored =
          d == 1 ? parameters.geometry.has_symmetry_boundary() :
          d == 2 ? parameters.geometry.has_symmetry_plane_z() :
                   false;
        center[d] = mirrored ? 0. : (momentum * position) / (momentum * along);
      }
    return center;
  }

  template <int dim>
  void
  ImpactSimulation<dim>::set_up_rotation(PETScWrappers::MPI::Vector &v)
  {
    const RigidWall<dim> wall          = parameters.contact.wall<dim>();
    const auto          &center        = rotation_center;
    auto                 along_tangent = op.create_vector();
    auto                 rotation      = op.create_vector();
    std::vector<double>  components(dim);
    for (unsigned int d = 0; d < dim; ++d)
      components[d] = wall.tangents()[0][d];
    VectorTools::interpolate(op.get_mapping(),
                             op.get_dof_handler(),
                             Functions::ConstantFunction<dim>(components),
                             along_tangent);
    // The rotation e_z x (x - c) is linear, so its interpolant is exact.
    VectorTools::interpolate(op.get_mapping(),
                             op.get_dof_handler(),
                             RotationField<dim>(center),
                             rotation);
    op.get_constraints().distribute(along_tangent);
    op.get_constraints().distribute(rotation);
    tangent_momentum = op.mass_functional(along_tangent);
    tangent_mass     = tangent_momentum * along_tangent;
    rotation_momentum = op.mass_functional(rotation);
    inertia           = rotation_momentum * rotation;
    if (zone->tracks_rotation())
      stepper->track_rotation(rotation, rotation_momentum);
    v.add(parameters.impact.tangential_velocity() * velocity_unit,
          along_tangent,
          parameters.impact.spin() * velocity_unit / radius,
          rotation);
    // As the discrete body moves: its centre of mass and the disk's centre
    // differ by the discretization.
    v_tangent_initial = mean_along_tangent(v);
    spin_initial      = mean_rotation(v);
  }

  template <int dim>
  double
  ImpactSimulation<dim>::mean_along_tangent(
    const PETScWrappers::MPI::Vector &x) const
  {
    return tracks_rotation ? (tangent_momentum * x) / tangent_mass : 0.;
  }

  template <int dim>
  double
  ImpactSimulation<dim>::mean_rotation(const PETScWrappers::MPI::Vector &x) const
  {
    return tracks_rotation ? (rotation_momentum * x) / inertia : 0.;
  }

  template <int dim>
  double
  ImpactSimulation<dim>::quadratic_form(
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const PETScWrappers::MPI::Vector       &x) const
  {
    return quadratic_form(matrix, x, product);
  }

  template <int dim>
  double
  ImpactSimulation<dim>::quadratic_form(
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

  template <int dim>
  double
  ImpactSimulation<dim>::mean_along_normal(
    const PETScWrappers::MPI::Vector &x) const
  {
    // Two bodies: the body's centre of mass relative to the partner's.
    if (bodies)
      return bodies->center_of_mass(0, x) - bodies->center_of_mass(1, x);
    return (normal_momentum * x) / normal_mass;
  }

  template <int dim>
  double
  ImpactSimulation<dim>::translational_energy(const double v_com) const
  {
    if (!bodies)
      return 0.5 * body_mass * v_com * v_com;
    double energy = 0.;
    for (unsigned int body = 0; body < 2; ++body)
      energy += 0.5 * domain_factor * bodies->mass(body) *
                std::pow(bodies->center_of_mass(body, stepper->velocity()), 2);
    return energy;
  }

  template <int dim>
  void
  ImpactSimulation<dim>::advance()
  {
    const double time = stepper->time();
    const auto   step = stepper->advance(dt);
    if (!step.converged)
      throw RunError(
        "impact: Newton's method did not converge at t = " +
        Utilities::to_string(time * velocity_unit / radius) +
        " R/c even with the time step "
        "halved " +
        std::to_string(parameters.time_integrator.max_step_cuts()) +
        " times; lower 'Time step fraction' or the 'Penalty factor'");
    dt    = step.dt;
    state = step.state;
    impulse += dt * domain_factor * state.force_average;
    tangential_impulse += dt * domain_factor * state.tangential_force_average[0];
    if (tracks_rotation && state.force_average > 0.)
      summary.oblique.rotation_in_contact =
        std::max(summary.oblique.rotation_in_contact,
                 std::abs(mean_rotation(stepper->displacement())));
    angular_impulse += dt * domain_factor * state.torque_average;
    friction_work += domain_factor * state.friction_work;
    dissipated += domain_factor * step.viscous_work;
    plastic_work += domain_factor * step.plastic_work;
    ++summary.steps;
  }

  template <int dim>
  void
  ImpactSimulation<dim>::record(const double time, const ContactState &step)
  {
    const auto &u = stepper->displacement();
    const auto &v = stepper->velocity();
    constraint_map.zeroed(v, work);
    const double kinetic =
      0.5 * domain_factor * (work * stepper->mass_times_velocity());
    const double strain = domain_factor * stepper->strain_energy();
    const double v_com = mean_along_normal(v);
    const double x_com = mean_along_normal(u) / radius;
    const double total  = kinetic + strain + domain_factor * step.energy +
                         dissipated + friction_work + plastic_work;
    // The step's mean force (its impulse / dt): the time discretization fixes
    // this mean, not the end-of-step force (docs/theory/impact-method.md).
    const double force = domain_factor * step.force_average / force_unit;
    energy_error =
      std::max(energy_error, std::abs(total - energy_initial) / energy_initial);
    energy_growth =
      std::max(energy_growth, (total - energy_initial) / energy_initial);
    // A run whose energy runs away (a thousandfold) is stopped here rather
    // than when its numbers overflow; a milder growth fails check_result().
    // The values are the same on every rank.
    if (!(energy_growth <= 1e3))
      throw RunError(
        "impact at v = " + approximately(impact_speed / velocity_unit, 6) +
        " c fails the check 'energy growth': the total energy "
        "grew by " +
        approximately(energy_growth) + " times its initial value by t = " +
        approximately(time * velocity_unit / radius) +
        " R/c (the time stepping is unstable for this contact)");
    series.start_row();
    for (const double value :
         {time * velocity_unit / radius,
          x_com,
          v_com / velocity_unit,
          force,
          step.half_width() / radius,
          kinetic,
          translational_energy(v_com),
          strain,
          domain_factor * step.energy,
          dissipated,
          friction_work,
          total,
          domain_factor * step.tangential_force_average[0] / force_unit,
          mean_along_tangent(v) / velocity_unit,
          mean_rotation(v) * radius / velocity_unit,
          plastic_work})
      series.add(value);
    summary.delta_max = std::max(summary.delta_max, -x_com);
    summary.contact_half_width_max =
      std::max(summary.contact_half_width_max, step.half_width() / radius);
    // The state of the largest force, where the contact's stress peaks
    // (record_stress_peak(), 2D models).
    if constexpr (dim == 2)
      if (force > summary.force_max)
        {
          largest_force_displacement = stepper->displacement();
          largest_force_half_width   = step.half_width();
        }
    summary.force_max = std::max(summary.force_max, force);
  }

  template <int dim>
  void
  ImpactSimulation<dim>::record_stress_peak()
  {
    // An elastic-plastic body's stress is not C : eps of the displacement.
    if (plasticity)
      {
        summary.von_mises_max = summary.von_mises_depth = std::nan("");
        return;
      }
    if constexpr (dim == 2)
      {
        // A Hertz contact yields below its centre, at depth 0.5a ... 0.8a:
        // the cells within three half-widths of the contact point (and the
        // contact's drift along the edge) hold the peak.
        if (largest_force_half_width <= 0.)
          return;
        const auto    &geometry = parameters.geometry;
        const Point<2> contact  = geometry.contact_point();
        const double   reach =
          3. * largest_force_half_width + contact_drift(parameters);
        const StressPeak peak =
          largest_von_mises(op.get_mapping(),
                            op.get_dof_handler(),
                            ImpactOperatorsBase::materials(parameters),
                            op.create_ghosted(largest_force_displacement),
                            contact,
                            reach);
        summary.von_mises_max =
          peak.von_mises / parameters.material.in_plane_young_modulus();
        summary.von_mises_depth =
          std::abs((peak.location - contact) * (geometry.center() - contact)) /
          (radius * radius);
      }
  }

  template <int dim>
  bool
  ImpactSimulation<dim>::collision_over()
  {
    // The collision ends when the step-mean force returns to zero (Schwager &
    // Pöschel 2007): the last two positive values, at mid-step, extrapolated to
    // zero within the step in which the force vanished.
    const double t          = stepper->time();
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
    if (contact_end >= 0. &&
        t >= contact_end * (1. + parameters.impact.time_after_contact()))
      return true;
    if (t > 20. * contact_time_estimate)
      throw RunError("impact: the contact has not ended after " +
                     Utilities::to_string(20. * contact_time_estimate *
                                          velocity_unit / radius) +
                     " R/c");
    older_force    = previous_force;
    older_time     = previous_time;
    previous_force = mean_force;
    previous_time  = mid_time;
    return false;
  }

  template <int dim>
  void
  ImpactSimulation<dim>::report_progress(
    const std::chrono::steady_clock::time_point start)
  {
    const auto now = std::chrono::steady_clock::now();
    if (!with_outputs || now - last_report < std::chrono::seconds(30))
      return;
    last_report = now;
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    const double elapsed  = std::chrono::duration<double>(now - start).count();
    const double fraction = stepper->time() / contact_time_estimate;
    std::ostringstream line;
    line.precision(4);
    line << "  t = " << stepper->time() * velocity_unit / radius << " R/c, "
         << std::lround(100. * fraction) << " % of the contact time expected, "
         << summary.steps << " steps in " << std::lround(elapsed) << " s";
    // The collision ends near the contact time expected.
    if (fraction > 0.05 && fraction < 1.)
      line << ", about " << std::lround(elapsed * (1. / fraction - 1.))
           << " s left";
    std::cout << line.str() << std::endl;
  }

  template <int dim>
  void
  ImpactSimulation<dim>::snapshot()
  {
    if (!with_outputs)
      return;
    const auto  ghosted_u = op.create_ghosted(stepper->displacement());
    const auto &directory = parameters.run.output_directory;
    // The record's times and fields in the units of the files (SI for an
    // SI run).
    const FieldScales scales = parameters.units.field_scales();
    const double time = stepper->time() * velocity_unit / radius * scales.time;
    const auto   materials = ImpactOperatorsBase::materials(parameters);
    // The contact's traction, for ParaView.
    if (!traction_field)
      traction_field = std::make_unique<ContactTraction<dim>>(op);
    const auto traction =
      (*traction_field)(zone->candidate_dofs(),
                        stepper->contact_force_on_candidates());
    // An elastic-plastic body: its plastic strain and von Mises stress
    // per cell instead of the elastic stress fields (and no revolved view,
    // which revolves those).
    std::vector<CellField> cells;
    if (plasticity)
      cells = plastic_cell_fields(*plasticity);
    if constexpr (dim == 2)
      if (parameters.impact.revolved_view() > 0. && !plasticity)
        {
          const auto [flat, revolved] =
            write_deformed_and_revolved_state(op,
                                              materials,
                                              ghosted_u,
                                              parameters.geometry.center(),
                                              radius,
                                              parameters.impact.revolved_view(),
                                              directory,
                                              "impact",
                                              snapshots.size(),
                                              scales,
                                              &traction);
          snapshots.emplace_back(time, flat);
          revolved_snapshots.emplace_back(time, revolved);
          return;
        }
    snapshots.emplace_back(time,
                           write_deformed_state(op,
                                                materials,
                                                ghosted_u,
                                                directory,
                                                "impact",
                                                snapshots.size(),
                                                scales,
                                                &traction,
                                                plasticity ? &cells : nullptr));
  }

  template <int dim>
  void
  ImpactSimulation<dim>::finish()
  {
    const auto  &u           = stepper->displacement();
    const auto  &v           = stepper->velocity();
    const double v_com_final = mean_along_normal(v);
    const double body_mass   = domain_factor * normal_mass;
    summary.epsilon          = -v_com_final / v_com_initial;
    summary.contact_time     = contact_end * velocity_unit / radius;
    summary.energy_error     = energy_error;
    if (parameters.contact.friction_coefficient() > 0.)
      summary.oblique.friction_work = friction_work / energy_initial;
    if (tracks_rotation)
      finish_oblique();
    if (bodies)
      finish_pair();
    else
      {
        summary.impulse_error =
          std::abs(body_mass * (v_com_final - v_com_initial) - impulse) /
          (body_mass * impact_speed);
        // The energy left in the body's vibration: all but the energy of
        // its rigid motion.
        const double strain = plasticity ?
                                stepper->strain_energy() :
                                quadratic_form(op.stiffness_matrix(), u);
        summary.vibration_fraction =
          (domain_factor * (quadratic_form(op.mass_matrix(), v) + strain) -
           rigid_motion_energy(v)) /
          energy_initial;
      }
    if (plasticity)
      {
        summary.plastic_work = plastic_work / energy_initial;
        summary.plastic_strain_max =
          plasticity->largest_equivalent_plastic_strain();
        summary.plastic_iterations = stepper->n_plastic_iterations();
        summary.tangent_factorizations = stepper->n_tangent_factorizations();
      }
    summary.newton_iterations     = stepper->n_newton_iterations();
    summary.factorizations        = stepper->n_factorizations();
    summary.triangular_solves     = stepper->n_triangular_solves();
    summary.time_step             = dt * velocity_unit / radius;
    summary.triangular_solve_time = stepper->triangular_solve_time();
    summary.contact_dofs          = stepper->n_contact_dofs();
    summary.peak_memory_mb        = peak_memory_mb(communicator);
  }

  template <int dim>
  void
  ImpactSimulation<dim>::finish_oblique()
  {
    // Velocities in units of c, the contact point's tangential velocity
    // v_t - omega R (the point of the rim nearest the wall; the wall's
    // tangent is e_z x n).
    const auto  &v       = stepper->velocity();
    const double c       = velocity_unit;
    const double v_t     = mean_along_tangent(v);
    const double omega   = mean_rotation(v);
    const double v_n     = -mean_along_normal(v);
    const double mass    = domain_factor * tangent_mass;
    auto        &oblique = summary.oblique;
    oblique.v_tangential_initial = v_tangent_initial / c;
    oblique.v_tangential_final   = v_t / c;
    oblique.spin_initial         = spin_initial * radius / c;
    oblique.spin_final           = omega * radius / c;
    oblique.v_contact_initial    = (v_tangent_initial - spin_initial * radius) / c;
    oblique.v_contact_final      = (v_t - omega * radius) / c;
    oblique.rebound_angle = std::atan2(v_t, -v_n) * 180. / M_PI;
    oblique.friction_work = friction_work / energy_initial;
    oblique.tangential_impulse_error =
      std::abs(mass * (v_t - v_tangent_initial) - tangential_impulse) /
      (body_mass * impact_speed);
    oblique.angular_impulse_error =
      std::abs(domain_factor * inertia * (omega - spin_initial) -
               angular_impulse) /
      (body_mass * impact_speed * radius);
    // Maw, Barber & Fawcett's angles without their material factor: the
    // contact point's tangential velocity over mu (1 + e) v_n / 2.
    const double mu = parameters.contact.friction_coefficient();
    if (mu > 0.)
      {
        const double scale =
          0.5 * mu * (1. + summary.epsilon) * impact_speed / c;
        oblique.psi_incident = oblique.v_contact_initial / scale;
        oblique.psi_rebound  = oblique.v_contact_final / scale;
      }
  }

  template <int dim>
  void
  ImpactSimulation<dim>::finish_pair()
  {
    // Each body's momentum change against the contact impulse (equal and
    // opposite on the two), relative to the reduced mass's m v_i; and the
    // energy left in each body's vibration: its energy less its centre of
    // mass's kinetic energy (of an elastic-plastic body with its residual
    // stresses, as strain_energy()).
    const auto  &u       = stepper->displacement();
    const auto  &v       = stepper->velocity();
    const double m1      = domain_factor * bodies->mass(0);
    const double m2      = domain_factor * bodies->mass(1);
    const double reduced = m1 * m2 / (m1 + m2);
    double       error   = 0.;
    for (unsigned int body = 0; body < 2; ++body)
      {
        const double m       = body == 0 ? m1 : m2;
        const double v_start = body == 0 ? -impact_speed * m2 / (m1 + m2) :
                                           impact_speed * m1 / (m1 + m2);
        const double v_end   = bodies->center_of_mass(body, v);
        error                = std::max(error,
                         std::abs(m * (v_end - v_start) -
                                  (body == 0 ? impulse : -impulse)));
        double strain = bodies->quadratic_form(body, op.stiffness_matrix(), u);
        if (plasticity)
          strain += plasticity->plastic_strain_energy(body) -
                    bodies->dot(body, u, stepper->current_plastic_force());
        const double vibration =
          domain_factor *
            (bodies->quadratic_form(body, op.mass_matrix(), v) + strain) -
          0.5 * m * v_end * v_end;
        (body == 0 ? summary.vibration_fraction :
                     summary.partner_vibration_fraction) =
          vibration / energy_initial;
      }
    summary.impulse_error  = error / (reduced * impact_speed);
    summary.momentum_error = std::abs(m1 * bodies->center_of_mass(0, v) +
                                      m2 * bodies->center_of_mass(1, v)) /
                             (reduced * impact_speed);
  }

  template <int dim>
  void
  ImpactSimulation<dim>::check_result() const
  {
    // Every value below is the same on all ranks: the error is collective.
    const auto fail = [&](const std::string &check, const std::string &what) {
      throw RunError(
        "impact at v = " + approximately(impact_speed / velocity_unit, 6) +
        " c fails the check '" + check + "': " + what);
    };
    const double eps = summary.epsilon;
    // With friction an oblique impact can turn energy of the motion along
    // the wall into the normal rebound (epsilon > 1, as Kuninaka & Hayakawa
    // found for elastic disks): then the body's rigid motion may at most
    // keep the initial energy.
    if (tracks_rotation && parameters.impact.is_oblique() &&
        parameters.contact.friction_coefficient() > 0.)
      {
        const double rigid = rigid_motion_energy(stepper->velocity());
        if (!(eps >= 0. && rigid <= energy_initial * (1. + 1e-6)))
          fail("0 <= epsilon, rigid motion's energy <= E(0)",
               "epsilon = " + approximately(eps, 6) +
                 ", the rigid motion keeps " +
                 approximately(rigid / energy_initial, 6) +
                 " of E(0): impossible for a passive body; " + likely_causes);
      }
    else if (!(eps >= 0. && eps <= 1. + 1e-6))
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
    // exponential wall, nor beyond the log law's range (NaN), nor for a
    // body that yields.
    if (!parameters.contact.approximates_hard_contact() || plasticity)
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

  template <int dim>
  void
  ImpactSimulation<dim>::write_outputs() const
  {
    const std::string &directory = parameters.run.output_directory;
    CsvTable           modes({"rank"});
    const auto        &u = stepper->displacement();
    const auto        &v = stepper->velocity();
    if (projection)
      modes = projection->table(u, v, energy_initial, domain_factor);
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
                 output_units(parameters),
                 parameters.units);
    });
  }

  template class ImpactSimulation<2>;
  template class ImpactSimulation<3>;

  ImpactSummary
  run_impact(const Parameters                    &parameters,
             MPI_Comm                             communicator,
             const bool                           write_time_series,
             std::shared_ptr<ImpactOperatorsBase> operators)
  {
    if (parameters.geometry.dimension() == 3)
      return ImpactSimulation<3>(parameters,
                                 communicator,
                                 write_time_series,
                                 std::dynamic_pointer_cast<ImpactOperators<3>>(
                                   operators))
        .run();
    return ImpactSimulation<2>(parameters,
                               communicator,
                               write_time_series,
                               std::dynamic_pointer_cast<ImpactOperators<2>>(
                                 operators))
      .run();
  }
} // namespace DiskImpact
