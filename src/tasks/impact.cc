#include "tasks/impact.h"

#include "contact_operator.h"
#include "csv_table.h"
#include "elasticity_operator.h"
#include "hdf5_output.h"
#include "input_error.h"
#include "low_rank_corrected_solver.h"
#include "modal_projection.h"
#include "parameters.h"
#include "reference/log_contact_law.h"
#include "reference/one_dof_impact.h"
#include "state_output.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function.h>
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The contact-law constant of the 1-DOF model: "fit" is the measured
    /// C_com = -1 - 2/pi - nu2/4 (docs/contact-law.md), else a number.
    double
    parse_contact_law_constant(const std::string &text, const double nu2)
    {
      if (text == "fit")
        return -1. - 2. / M_PI - nu2 / 4.;
      try
        {
          return std::stod(text);
        }
      catch (const std::exception &)
        {
          throw InputError("Impact: 'Contact law constant' must be 'fit' or "
                           "a number, got '" +
                           text + "'");
        }
    }

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
               const std::vector<double> &velocity)
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
      file.set_attribute("/",
                         "units",
                         "lengths R, times R/c, velocities c = sqrt(E2/rho), "
                         "forces E2 R, energies E2 R^2 (per unit thickness)");
      file.finish();
    }
  } // namespace

  void
  Impact::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact");
    prm.declare_entry("Velocity",
                      "0.01",
                      Patterns::Double(),
                      "Impact speed v_i in units of c = sqrt(E2 / rho) [-], "
                      "0 < v_i <= 0.5.");
    prm.declare_entry("Elements across contact",
                      "12",
                      Patterns::Integer(4, 1000),
                      "Elements across the largest Hertz half-width expected "
                      "(from the 1-DOF model's largest force); the mesh is "
                      "graded toward the contact point as in task "
                      "'quasistatic contact'.");
    prm.declare_entry("Grading",
                      "0.3",
                      Patterns::Double(0.01, 1),
                      "Growth of the element size with distance from the "
                      "contact zone [-].");
    prm.declare_entry("Contact law constant",
                      "fit",
                      Patterns::Anything(),
                      "Constant C of the log law in the 1-DOF reference model "
                      "(time-step estimate, comparison): 'fit' for the "
                      "measured centre-of-mass law C = -1 - 2/pi - nu2/4, or "
                      "a number.");
    prm.declare_entry("Output interval",
                      "20",
                      Patterns::Integer(0),
                      "Write the deformed state with stresses (impact.pvd) "
                      "every this many steps; 0: only the final state.");
    prm.declare_entry("Mode energies",
                      "20",
                      Patterns::Integer(0, 400),
                      "Task 'impact': project the vibration on this many "
                      "lowest elastic eigenmodes of the same discretization "
                      "(mode_energies.csv: after the impact and averaged over "
                      "the collision, as seed 001's Table 1); 0: none.");
    prm.declare_entry("Velocities",
                      "0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3",
                      Patterns::List(Patterns::Double(), 0),
                      "Task 'sweep': the impact speeds v_i / c [-].");
    prm.declare_entry("Poisson ratios",
                      "",
                      Patterns::List(Patterns::Double(), 0),
                      "Task 'sweep': Poisson ratios (as 'Poisson ratio' of "
                      "subsection Material) [-]; empty: the material's.");
    prm.declare_entry("Error estimate",
                      "true",
                      Patterns::Bool(),
                      "Task 'sweep': run a convergence study (subsection "
                      "Impact convergence) at each point and report its "
                      "extrapolated epsilon and error bar (epsilon, "
                      "epsilon_error); false: one run per point, no error "
                      "bar.");
    prm.declare_entry("Margin",
                      "0.2",
                      Patterns::Double(0., 10.),
                      "Time simulated after the contact force has returned to "
                      "zero, as a fraction of the contact time [-].");
    prm.leave_subsection();
  }

  void
  Impact::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact");
    impact_velocity         = prm.get_double("Velocity");
    elements_across_contact = prm.get_integer("Elements across contact");
    grading                 = prm.get_double("Grading");
    contact_law_constant    = prm.get("Contact law constant");
    margin                  = prm.get_double("Margin");
    output_interval         = prm.get_integer("Output interval");
    projected_modes         = prm.get_integer("Mode energies");
    sweep_velocities        = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Velocities"), ','));
    sweep_poisson_ratios = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Poisson ratios"), ','));
    error_estimate = prm.get_bool("Error estimate");
    for (const double v : sweep_velocities)
      require(v > 0. && v <= 0.5,
              "Impact: every entry of 'Velocities' must satisfy 0 < v/c <= "
              "0.5, got " +
                Utilities::to_string(v));
    prm.leave_subsection();
    require(impact_velocity > 0. && impact_velocity <= 0.5,
            "Impact: 'Velocity' must satisfy 0 < v/c <= 0.5, got " +
              Utilities::to_string(impact_velocity));
    if (contact_law_constant != "fit")
      parse_contact_law_constant(contact_law_constant, 0.);
  }

  double
  Impact::velocity() const
  {
    return impact_velocity;
  }

  void
  Impact::set_velocity(const double v)
  {
    impact_velocity = v;
  }

  const std::vector<double> &
  Impact::velocities() const
  {
    return sweep_velocities;
  }

  const std::vector<double> &
  Impact::poisson_ratios() const
  {
    return sweep_poisson_ratios;
  }

  bool
  Impact::estimate_errors() const
  {
    return error_estimate;
  }

  Impact
  Impact::with_mesh_refined(const unsigned int levels) const
  {
    Impact finer                  = *this;
    finer.elements_across_contact = elements_across_contact << levels;
    finer.grading                 = grading / (1u << levels);
    return finer;
  }

  ImpactSummary
  Impact::run(const Parameters &parameters,
              MPI_Comm          communicator,
              const bool        write_time_series) const
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    ConditionalOStream pcout(std::cout, root);
    const auto        &geometry   = parameters.geometry;
    const auto        &material   = parameters.material;
    const auto        &integrator = parameters.time_integrator;
    const RigidWall   &wall       = parameters.contact.wall();

    const double R      = geometry.radius();
    const double E2     = material.in_plane_young_modulus();
    const double c      = material.velocity_unit();
    const double v0     = impact_velocity * c;
    const double mass   = material.density() * M_PI * R * R;
    const double factor = geometry.is_half_disk() ? 2. : 1.;

    // The 1-DOF log-law collision: contact time (time step) and largest
    // force (mesh); beyond the law's range, seed 001's eq. 61 estimates.
    ImpactSummary summary;
    summary.velocity = impact_velocity;
    const double C =
      parse_contact_law_constant(contact_law_constant,
                                 material.in_plane_poisson_ratio());
    double contact_time_estimate, largest_load;
    try
      {
        const auto one_dof    = Reference::one_dof_impact(v0, mass, E2, R, C);
        contact_time_estimate = one_dof.contact_time;
        largest_load          = one_dof.max_force / (M_PI * E2 * R);
        summary.one_dof_contact_time = one_dof.contact_time * c / R;
        summary.one_dof_delta_max    = one_dof.max_compression / R;
      }
    catch (const std::domain_error &)
      {
        const double delta =
          impact_velocity * R * std::sqrt(std::log(4. / impact_velocity));
        contact_time_estimate = M_PI * delta / v0;
        largest_load          = delta / (R * std::log(4. * R / delta));
      }

    // Mesh graded for the largest contact, operators, penalty.
    parallel::distributed::Triangulation<2> triangulation(
      communicator, Triangulation<2>::limit_level_difference_at_vertices);
    geometry.create_triangulation(triangulation);
    const double largest_half_width =
      Reference::hertz_half_width(largest_load) * R;
    refine_toward_contact(triangulation,
                          geometry.contact_point(),
                          largest_half_width,
                          elements_across_contact,
                          grading);
    ElasticityOperator op(parameters.finite_element.degree);
    op.setup(triangulation, geometry, true);
    // No inertia on the edge within the uniformly refined contact zone.
    if (integrator.redistribute_mass())
      op.set_massless_edge_zone(geometry.contact_point(),
                                1.5 * largest_half_width);
    op.assemble(material);
    summary.massless_dofs = op.n_massless_dofs();
    // The modes to project on, of the operator the time stepping uses.
    std::unique_ptr<ModalProjection> projection;
    if (write_time_series && projected_modes > 0)
      projection = std::make_unique<ModalProjection>(
        op,
        geometry,
        std::pow(material.transverse_wave_speed() / R, 2),
        projected_modes);
    const ContactOperator contact(
      op,
      wall,
      parameters.contact.penalty_law(E2,
                                     ContactOperator::smallest_edge_face(op)),
      geometry.center());
    const auto &constraints = op.get_constraints();
    summary.n_dofs          = op.get_dof_handler().n_dofs();
    // State: at rest relative to a uniform motion toward the wall.
    auto u = op.create_vector(), v = op.create_vector(), a = op.create_vector(),
         along_normal = op.create_vector();
    VectorTools::interpolate(op.get_mapping(),
                             op.get_dof_handler(),
                             Functions::ConstantFunction<2>(std::vector<double>{
                               wall.normal[0], wall.normal[1]}),
                             along_normal);
    constraints.distribute(along_normal);
    v.add(-v0, along_normal);
    auto u_new = op.create_vector(), v_new = op.create_vector(),
         a_new = op.create_vector(), w = op.create_vector(),
         b = op.create_vector(), r = op.create_vector(),
         du = op.create_vector(), tmp = op.create_vector();

    auto quadratic_form = [&](const PETScWrappers::MPI::SparseMatrix &matrix,
                              const PETScWrappers::MPI::Vector       &x) {
      // On the condensed matrices, x with its constrained entries zeroed
      // gives the form of the unconstrained field.
      w = x;
      constraints.set_zero(w);
      matrix.vmult(tmp, w);
      return 0.5 * (w * tmp);
    };
    // The centre of mass's motion along the wall normal: the momentum
    // (M x) . n over the mass n . M n, which holds for a redistributed mass.
    const double normal_mass = op.mass_product(along_normal, along_normal);
    // The discrete disk's mass (whole disk), for the momentum balance.
    const double discrete_mass     = factor * normal_mass;
    auto         mean_along_normal = [&](const PETScWrappers::MPI::Vector &x) {
      return op.mass_product(x, along_normal) / normal_mass;
    };

    const double energy_initial = factor * quadratic_form(op.mass_matrix(), v);
    double       energy_error   = 0.;
    double       impulse        = 0.;
    const double v_com_initial  = mean_along_normal(v);

    CsvTable series = time_series_table();
    auto     record = [&](const double t, const ContactState &state) {
      const double kinetic = factor * quadratic_form(op.mass_matrix(), v);
      const double strain = factor * quadratic_form(op.stiffness_matrix(), u);
      const double v_com = mean_along_normal(v);
      const double x_com = mean_along_normal(u) / R;
      const double total = kinetic + strain + factor * state.energy;
      energy_error =
        std::max(energy_error,
                 std::abs(total - energy_initial) / energy_initial);
      series.start_row();
      for (const double value : {t * c / R,
                                 x_com,
                                 v_com / c,
                                 factor * state.force_average / (E2 * R),
                                 state.half_width() / R,
                                 kinetic,
                                 0.5 * mass * v_com * v_com,
                                 strain,
                                 factor * state.energy,
                                 0.,
                                 total})
        series.add(value);
      summary.delta_max = std::max(summary.delta_max, -x_com);
      summary.force_max =
        std::max(summary.force_max, factor * state.force_average / (E2 * R));
    };
    record(0., ContactState());

    // ParaView snapshots every 'Output interval' steps, and the final state.
    std::vector<std::pair<double, std::string>> snapshots;
    auto snapshot = [&](const double time) {
      if (write_time_series)
        snapshots.emplace_back(
          time * c / R,
          write_deformed_state(op,
                               material,
                               op.create_ghosted(u),
                               parameters.run.output_directory,
                               "impact",
                               snapshots.size()));
    };
    if (output_interval > 0)
      snapshot(0.);

    // Effective matrix A = cm M + (1 - af) K, factorized once per step size.
    double dt = integrator.time_step(contact_time_estimate);
    std::unique_ptr<LowRankCorrectedSolver> solver;
    auto                                    factorize = [&]() {
      auto &A = op.tangent_reset_to_stiffness();
      A *= integrator.stiffness_coefficient();
      A.add(integrator.mass_coefficient(dt), op.mass_matrix());
      solver = std::make_unique<LowRankCorrectedSolver>(A,
                                                        op.locally_owned_dofs(),
                                                        communicator);
    };
    factorize();
    unsigned int factorizations_before = 0, solves_before = 0;
    double       solve_time_before = 0.;

    // One step from (u, v) to (u_new, v_new); false if Newton fails.
    std::vector<RankOneTerm> terms;
    ContactState             state;
    auto                     attempt_step = [&]() {
      const double force_scale = 2. / dt * std::sqrt(2. * energy_initial);
      integrator.inertia_vector(u, v, a, dt, w);
      op.mass_matrix().vmult(b, w);
      op.stiffness_matrix().vmult(tmp, u);
      b.add(-integrator.old_stiffness_weight(), tmp);
      TimeIntegrator::predictor(u, v, dt, u_new);
      constraints.distribute(u_new);
      const auto ghosted_u = op.create_ghosted(u);
      for (unsigned int it = 0; it <= integrator.max_newton_iterations(); ++it)
        {
          auto &A = op.tangent_matrix();
          A.vmult(r, u_new);
          r -= b;
          state = contact.assemble_step(ghosted_u,
                                        op.create_ghosted(u_new),
                                        integrator.contact_average(),
                                        integrator.contact_new_weight(),
                                        r,
                                        &terms);
          r.compress(VectorOperation::add);
          constraints.set_zero(r);
          if (r.l2_norm() <= integrator.newton_tolerance() * force_scale)
            {
              summary.newton_iterations += it;
              return true;
            }
          if (it == integrator.max_newton_iterations())
            break;
          r *= -1.;
          solver->solve(terms, r, du);
          constraints.distribute(du);
          u_new += du;
        }
      return false;
    };

    const auto   start          = std::chrono::steady_clock::now();
    double       t              = 0.;
    double       contact_end    = -1.;
    double       previous_force = 0., previous_time = 0.;
    double       older_force = 0., older_time = -1.;
    unsigned int cuts  = 0;
    const double t_max = 20. * contact_time_estimate;
    for (;;)
      {
        if (!attempt_step())
          {
            if (++cuts > integrator.max_step_cuts())
              throw std::runtime_error(
                "impact: Newton's method did not converge at t = " +
                Utilities::to_string(t * c / R) +
                " R/c even with the time "
                "step halved " +
                std::to_string(integrator.max_step_cuts()) +
                " times; lower 'Time step fraction' or raise 'Penalty "
                "factor'-independent tolerances");
            factorizations_before += solver->n_factorizations();
            solves_before += solver->n_triangular_solves();
            solve_time_before += solver->triangular_solve_time();
            dt *= 0.5;
            factorize();
            continue;
          }
        integrator.update(u, u_new, v, a, dt, v_new, a_new);
        constraints.distribute(v_new);
        constraints.distribute(a_new);
        impulse += dt * factor * state.force_average;
        u = u_new;
        v = v_new;
        a = a_new;
        t += dt;
        ++summary.steps;
        record(t, state);
        if (projection && state.force_average > 0.)
          projection->add_sample(u, v, dt);
        if (output_interval > 0 && summary.steps % output_interval == 0)
          snapshot(t);

        // The collision ends when the force returns to zero (seed 002);
        // the zero crossing is interpolated linearly.
        // The step's mean force (its impulse / dt), at the step's middle:
        // the time discretization fixes this mean, not the end-of-step
        // force, which can alternate from step to step (docs/impact.md).
        const double mean_force = state.force_average;
        const double mid_time   = t - 0.5 * dt;
        if (mean_force > 0.)
          contact_end = -1.;
        else if (contact_end < 0. && previous_force > 0.)
          {
            // extrapolate the last two positive forces to zero, within
            // the step in which the force vanished
            const double slope =
              (previous_force - older_force) / (previous_time - older_time);
            contact_end =
              slope < 0. ? std::min(t, previous_time - previous_force / slope) :
                           previous_time;
          }
        if (contact_end >= 0. && t >= contact_end * (1. + margin))
          break;
        if (t > t_max)
          throw std::runtime_error("impact: the contact has not ended after " +
                                   Utilities::to_string(t_max * c / R) +
                                   " R/c");
        older_force    = previous_force;
        older_time     = previous_time;
        previous_force = mean_force;
        previous_time  = mid_time;
      }
    summary.wall_time_loop =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();

    const double v_com_final = mean_along_normal(v);
    summary.epsilon          = -v_com_final / v_com_initial;
    summary.contact_time     = contact_end * c / R;
    summary.energy_error     = energy_error;
    summary.impulse_error =
      std::abs(discrete_mass * (v_com_final - v_com_initial) - impulse) /
      (discrete_mass * v0);
    summary.factorizations = factorizations_before + solver->n_factorizations();
    summary.triangular_solves = solves_before + solver->n_triangular_solves();
    summary.time_step         = dt * c / R;
    summary.triangular_solve_time =
      (solve_time_before + solver->triangular_solve_time()) /
      summary.triangular_solves;
    summary.contact_dofs = solver->n_contact_dofs();

    snapshot(t);
    if (!write_time_series)
      return summary;
    const std::string &directory = parameters.run.output_directory;
    CsvTable           modes({"rank"});
    if (projection)
      modes = projection->table(u, v, energy_initial, factor);
    const auto final_u = gather_on_root(u, communicator),
               final_v = gather_on_root(v, communicator);
    if (root)
      {
        series.write(directory + "/impact.csv");
        std::ofstream pvd(directory + "/impact.pvd");
        DataOutBase::write_pvd_record(pvd, snapshots);
        if (projection)
          modes.write(directory + "/mode_energies.csv");
        write_hdf5(
          directory + "/impact.h5", summary, series, modes, final_u, final_v);
      }
    return summary;
  }

  void
  Impact::write_summary(const ImpactSummary &s, const std::string &filename)
  {
    summary_table(s).write(filename);
  }

  CsvTable
  Impact::summary_table(const ImpactSummary &s)
  {
    CsvTable table({"velocity",
                    "epsilon",
                    "contact_time",
                    "delta_max",
                    "force_max",
                    "energy_error",
                    "steps",
                    "newton_iterations",
                    "impulse_error",
                    "time_step",
                    "n_dofs",
                    "factorizations",
                    "triangular_solves",
                    "one_dof_contact_time",
                    "one_dof_delta_max"});
    table.start_row();
    for (const double value : {s.velocity,
                               s.epsilon,
                               s.contact_time,
                               s.delta_max,
                               s.force_max,
                               s.energy_error})
      table.add(value);
    table.add(s.steps);
    table.add(s.newton_iterations);
    table.add(s.impulse_error);
    table.add(s.time_step);
    table.add(s.n_dofs);
    table.add(s.factorizations);
    table.add(s.triangular_solves);
    table.add(s.one_dof_contact_time);
    table.add(s.one_dof_delta_max);
    return table;
  }
} // namespace DiskImpact
