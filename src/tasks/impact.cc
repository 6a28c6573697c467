#include "tasks/impact.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "base/renamed_entries.h"
#include "body/geometry.h"
#include "output/csv_table.h"
#include "reference/collision_estimate.h"
#include "reference/hertz_impact.h"
#include "reference/log_contact_law.h"
#include "reference/sphere_finite_size.h"
#include "reference/two_body_contact.h"
#include "reference/viscoelastic_spheres.h"
#include "reference/wall_contact_theory.h"
#include "tasks/impact_simulation.h"
#include "tasks/parameters.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The contact-law constant of the 1-DOF model. A disk's: "exact" is
    /// the centre-of-mass constant C_com = -2 ln 2 - (1 + nu2)/4, "fit" the
    /// earlier fit -1 - 2/pi - nu2/4 to the FE
    /// (docs/validation/disk-contact-law.md). A sphere's finite-size
    /// constant D: "exact" is Hertz's law (D = 0), the limit a / R -> 0.
    /// Else a number.
    double
    parse_contact_law_constant(const std::string &text,
                               const double       nu2,
                               const bool         sphere)
    {
      if (text == "exact")
        return sphere ? 0. : Reference::centre_of_mass_constant(nu2);
      require(!(sphere && text == "fit"),
              "Impact: 'One-DOF law constant = fit' is the disk's log-law "
              "fit; a sphere takes 'exact' (Hertz, D = 0) or a number D");
      if (text == "fit")
        return -1. - 2. / M_PI - nu2 / 4.;
      // The whole text must be one finite number ("1x" is not).
      std::istringstream stream(text);
      double             value = 0.;
      stream >> value;
      require(!stream.fail() && (stream >> std::ws).eof() &&
                std::isfinite(value),
              "Impact: 'One-DOF law constant' must be 'exact', 'fit' or a "
              "finite number, got '" +
                text + "'");
      return value;
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
                      "0 < v_i <= 0.5; with a partner body (subsection "
                      "Partner) the relative speed, 0 < v_i <= 1.");
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
    prm.declare_entry("Fine zone radius",
                      Utilities::to_string(default_fine_zone_radius),
                      Patterns::Double(0., 10.),
                      "Radius of the zone around the contact point whose "
                      "elements all have the finest size (the half-width "
                      "over 'Elements across contact'), in units of the "
                      "graded half-width [-]; beyond it the size grows by "
                      "'Grading'. Below 1 the contact zone's edge lies in "
                      "the growing elements, which quartic elements allow "
                      "(docs/validation/elastic-disk-restitution.md).");
    prm.declare_entry("Graded half-width",
                      "0",
                      Patterns::Double(0., 1.),
                      "Half-width of the contact zone the mesh is graded for "
                      "[R]; 0: Hertz's half-width at the 1-DOF model's "
                      "largest force at this speed. A fixed value keeps one "
                      "mesh for every speed of a sweep (epsilon(v) on one "
                      "discretization).");
    prm.declare_entry("One-DOF law constant",
                      "exact",
                      Patterns::Anything(),
                      "Constant of the wall law in the 1-DOF reference model "
                      "(the quasistatic one-degree-of-freedom collision that "
                      "estimates the contact time, the time step and the "
                      "graded mesh, and that the results are compared with). "
                      "Disk: C of the log "
                      "law, 'exact' for the centre-of-mass law C = -2 ln 2 - "
                      "(1 + nu2)/4, 'fit' for the fitted C = -1 - 2/pi "
                      "- nu2/4, or a number. Sphere: the finite-size constant "
                      "D of delta = delta_Hertz + D P / (E* R), 'exact' for "
                      "Hertz's law (D = 0), 'finite size' for the derived "
                      "D = D0 + D1 ln(a/R) at the contact radius of Hertz's "
                      "largest approach (on the wall, or in a pair the "
                      "pair's, with each sphere's own nu and R), or a "
                      "number.");
    prm.declare_entry("Output interval",
                      "20",
                      Patterns::Integer(0),
                      "Write the deformed state with stresses (impact.pvd) "
                      "every this many steps; 0: only the final state.");
    prm.declare_entry("Revolved view",
                      "0",
                      Patterns::Double(0., 360.),
                      "A sphere only: with each state of impact.pvd also "
                      "write a 3D view (impact_3d.pvd), the meridian "
                      "revolved about the axis through this angle in degrees "
                      "(the surface and the two cut planes; 270 shows the "
                      "inside); 0: none.");
    prm.declare_entry("Number of projected modes",
                      "20",
                      Patterns::Integer(0, 400),
                      "Task 'impact': project the vibration on this many "
                      "lowest elastic eigenmodes of the same discretization "
                      "(mode_energies.csv: after the impact and averaged over "
                      "the collision, as Gerl & Zippelius' Table 1); 0: none.");
    prm.declare_entry("Velocities",
                      "0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3",
                      Patterns::List(Patterns::Double(), 0),
                      "Task 'sweep': the impact speeds v_i / c [-].");
    prm.declare_entry("Poisson ratios",
                      "",
                      Patterns::List(Patterns::Double(), 0),
                      "Task 'sweep': Poisson ratios (as 'Poisson ratio' of "
                      "subsection Material) [-]; empty: the material's.");
    prm.declare_entry("Relaxation times",
                      "",
                      Patterns::List(Patterns::Double(0.), 0),
                      "Task 'sweep': Kelvin-Voigt relaxation times (as "
                      "'Relaxation time' of subsection Material) [time]; "
                      "empty: the material's.");
    prm.declare_entry("Partner radii",
                      "",
                      Patterns::List(Patterns::Double(0.), 0),
                      "Task 'sweep' with 'Kind = body' in subsection Partner: "
                      "the partner's radii (as its 'Radius') [R], each with "
                      "every velocity; empty: the partner's 'Radius'.");
    prm.declare_entry("Convergence study per point",
                      "true",
                      Patterns::Bool(),
                      "Task 'sweep': run a convergence study (subsection "
                      "Impact convergence) at each point and report its "
                      "extrapolated epsilon and error bar (epsilon, "
                      "epsilon_error); false: one run per point, no error "
                      "bar.");
    prm.declare_entry("Resume",
                      "true",
                      Patterns::Bool(),
                      "Task 'sweep': keep the finished points of an earlier "
                      "sweep of the same parameters in the output directory "
                      "(restitution.csv) and compute only the others; a "
                      "table of other parameters there is an error. false: "
                      "start afresh, removing the earlier table.");
    prm.declare_entry("Time after contact",
                      "0.2",
                      Patterns::Double(0., 10.),
                      "Time simulated after the contact force has returned to "
                      "zero, as a fraction of the contact time [-].");
    declare_renamed_entry(prm,
                          "Impact",
                          "One-DOF law constant",
                          "Contact law constant");
    declare_renamed_entry(prm,
                          "Impact",
                          "Number of projected modes",
                          "Mode energies");
    declare_renamed_entry(prm,
                          "Impact",
                          "Convergence study per point",
                          "Error estimate");
    declare_renamed_entry(prm, "Impact", "Time after contact", "Margin");
    prm.leave_subsection();
  }

  void
  Impact::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact");
    impact_velocity         = prm.get_double("Velocity");
    elements_across_contact = prm.get_integer("Elements across contact");
    grading                 = prm.get_double("Grading");
    fine_zone_radius        = prm.get_double("Fine zone radius");
    graded_half_width       = prm.get_double("Graded half-width");
    contact_law_constant    = prm.get("One-DOF law constant");
    margin                  = prm.get_double("Time after contact");
    output_interval         = prm.get_integer("Output interval");
    revolved_view_angle     = prm.get_double("Revolved view");
    projected_modes         = prm.get_integer("Number of projected modes");
    sweep_velocities        = get_double_list(prm, "Velocities");
    sweep_poisson_ratios    = get_double_list(prm, "Poisson ratios");
    sweep_relaxation_times  = get_double_list(prm, "Relaxation times");
    sweep_partner_radii     = get_double_list(prm, "Partner radii");
    error_estimate          = prm.get_bool("Convergence study per point");
    resume_sweep            = prm.get_bool("Resume");
    prm.leave_subsection();
    check_velocities(1.);
    if (contact_law_constant != "finite size")
      parse_contact_law_constant(contact_law_constant, 0., false);
  }

  void
  Impact::check_velocities(const double largest) const
  {
    const std::string range =
      "0 < v/c <= " + Utilities::to_string(largest) +
      (largest > 0.5 ? " (the relative speed of two bodies)" : "");
    require_each(
      sweep_velocities,
      [&](const double v) { return v > 0. && v <= largest; },
      "Impact: every entry of 'Velocities' must satisfy " + range);
    require(impact_velocity > 0. && impact_velocity <= largest,
            "Impact: 'Velocity' must satisfy " + range + ", got " +
              approximately(impact_velocity, 6));
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

  const std::vector<double> &
  Impact::relaxation_times() const
  {
    return sweep_relaxation_times;
  }

  const std::vector<double> &
  Impact::partner_radii() const
  {
    return sweep_partner_radii;
  }

  bool
  Impact::estimate_errors() const
  {
    return error_estimate;
  }

  bool
  Impact::resume() const
  {
    return resume_sweep;
  }

  Impact
  Impact::with_mesh_refined(const unsigned int levels) const
  {
    Impact finer                  = *this;
    finer.elements_across_contact = elements_across_contact << levels;
    finer.grading                 = grading / (1u << levels);
    return finer;
  }

  double
  Impact::contact_law_constant_value(const Parameters &parameters) const
  {
    if (contact_law_constant == "finite size")
      return finite_size_constant(parameters, hertz_contact_radius(parameters));
    return parse_contact_law_constant(
      contact_law_constant,
      parameters.material.in_plane_poisson_ratio(),
      parameters.geometry.is_axisymmetric());
  }

  double
  Impact::hertz_contact_radius(const Parameters &parameters) const
  {
    // Hertz's impact of the sphere on the wall, or of the pair as its
    // equivalent body with the reduced mass; a^2 = R_eff delta_max.
    const auto  &material = parameters.material;
    const double v0       = impact_velocity * material.velocity_unit();
    double       mass     = material.density() * parameters.geometry.volume();
    Reference::ContactBody body{parameters.geometry.radius(),
                                material.in_plane_young_modulus(),
                                0.};
    const auto            &partner = parameters.partner;
    if (partner.is_body())
      {
        const double m2 =
          partner.material().density() *
          parameters.geometry.with_radius(partner.radius()).volume();
        mass = mass * m2 / (mass + m2);
        body = Reference::equivalent_body(
          true,
          body,
          {partner.radius(), partner.material().in_plane_young_modulus(), 0.});
      }
    return std::sqrt(
      body.radius *
      Reference::hertz_sphere_impact(mass, body.modulus, body.radius, v0)
        .max_overlap);
  }

  double
  Impact::finite_size_constant(const Parameters &body,
                               const double      contact_radius) const
  {
    require(body.geometry.is_axisymmetric(),
            "Impact: 'One-DOF law constant = finite size' is the sphere's "
            "law; a disk takes 'exact', 'fit' or a number");
    // D = D0 + D1 ln(a/R) (docs/theory/sphere-finite-size.md).
    return Reference::sphere_finite_size_term(
      Reference::sphere_finite_size_constants(body.material.poisson_ratio()),
      contact_radius / body.geometry.radius());
  }

  void
  Impact::check_time_step(const Parameters &parameters) const
  {
    parameters.time_integrator.check_time_step(
      estimate_collision(parameters).contact_time);
  }

  CollisionEstimate
  Impact::estimate_collision(const Parameters &parameters) const
  {
    if (parameters.partner.is_body())
      return estimate_pair_collision(parameters);
    const auto &material = parameters.material;
    return Reference::estimate_wall_collision(
      {parameters.geometry.is_axisymmetric(),
       material.density() * parameters.geometry.volume(),
       impact_velocity,
       material.velocity_unit(),
       material.in_plane_young_modulus(),
       parameters.geometry.radius(),
       contact_law_constant_value(parameters),
       material.relaxation_time()});
  }

  std::pair<Reference::ContactBody, Reference::ContactBody>
  Impact::contact_bodies(const Parameters &parameters) const
  {
    const auto &partner      = parameters.partner;
    Parameters  partner_only = parameters;
    partner_only.material    = partner.material();
    partner_only.geometry = parameters.geometry.with_radius(partner.radius());
    return {{parameters.geometry.radius(),
             parameters.material.in_plane_young_modulus(),
             contact_law_constant_value(parameters)},
            {partner.radius(),
             partner.material().in_plane_young_modulus(),
             contact_law_constant == "finite size" ?
               finite_size_constant(partner_only,
                                    hertz_contact_radius(parameters)) :
               contact_law_constant_value(partner_only)}};
  }

  CollisionEstimate
  Impact::estimate_pair_collision(const Parameters &parameters) const
  {
    const auto &partner      = parameters.partner;
    const auto [body, other] = contact_bodies(parameters);
    return Reference::estimate_pair_collision(
      {parameters.geometry.is_axisymmetric(),
       parameters.material.density() * parameters.geometry.volume(),
       partner.material().density() *
         parameters.geometry.with_radius(partner.radius()).volume(),
       impact_velocity,
       parameters.material.velocity_unit(),
       parameters.geometry.radius(),
       body,
       other,
       parameters.material.relaxation_time(),
       partner.material().relaxation_time()});
  }

  double
  Impact::contact_modulus(const Parameters &parameters)
  {
    const double E2 = parameters.material.in_plane_young_modulus();
    if (!parameters.partner.is_body())
      return E2;
    const double E2_partner =
      parameters.partner.material().in_plane_young_modulus();
    return 1. / (1. / E2 + 1. / E2_partner);
  }

  double
  Impact::dissipation_parameter(const Parameters &parameters) const
  {
    const auto  &material = parameters.material;
    const double R        = parameters.geometry.radius();
    const double E2       = material.in_plane_young_modulus();
    const double mass     = material.density() * parameters.geometry.volume();
    const double tau      = material.relaxation_time();
    if (!parameters.geometry.is_axisymmetric())
      // Schwager's alpha = A sqrt(pi E2 / m) with A = tau (Schwager 2007).
      return tau * std::sqrt(M_PI * E2 / mass);
    // Ramírez et al.'s u = (v / g*)^{1/5} with A = tau, eq. 32.
    if (!(tau > 0.))
      return 0.;
    return Reference::sphere_scaled_velocity(
      mass,
      Reference::hertz_sphere_stiffness(E2, R),
      tau,
      impact_velocity * material.velocity_unit());
  }

  double
  Impact::force_unit(const Parameters &parameters)
  {
    const double R = parameters.geometry.radius();
    return parameters.material.in_plane_young_modulus() * R *
           (parameters.geometry.is_axisymmetric() ? R : 1.);
  }

  std::string
  Impact::units(const Parameters &parameters)
  {
    return parameters.geometry.is_axisymmetric() ?
             "lengths R, times R/c, velocities c = sqrt(E*/rho) with E* = "
             "E/(1-nu^2), forces E* R^2, energies E* R^3 (the whole sphere)" :
             "lengths R, times R/c, velocities c = sqrt(E2/rho), forces E2 "
             "R, energies E2 R^2 (per unit thickness)";
  }

  double
  Impact::graded_width(const Parameters &parameters) const
  {
    if (graded_half_width > 0.)
      return graded_half_width * parameters.geometry.radius();
    return largest_half_width(parameters);
  }

  double
  Impact::largest_half_width(const Parameters &parameters) const
  {
    return Reference::wall_contact_theory(parameters.geometry.is_axisymmetric())
             ->half_width(estimate_collision(parameters).largest_load) *
           parameters.geometry.radius();
  }

  void
  Impact::create_mesh(const Parameters &parameters,
                      Triangulation<2> &triangulation,
                      const double      max_cells) const
  {
    const auto &geometry = parameters.geometry;
    if (parameters.partner.is_body())
      parameters.partner.create_pair_triangulation(geometry,
                                                   triangulation,
                                                   max_cells);
    else
      geometry.create_triangulation(triangulation, max_cells);
    refine_toward_contact(triangulation,
                          geometry.contact_point(),
                          graded_width(parameters),
                          elements_across_contact,
                          grading,
                          fine_zone_radius,
                          max_cells);
  }

  ImpactSummary
  Impact::run(const Parameters                &parameters,
              MPI_Comm                         communicator,
              const bool                       write_time_series,
              std::shared_ptr<ImpactOperators> operators) const
  {
    return ImpactSimulation(parameters,
                            *this,
                            communicator,
                            write_time_series,
                            std::move(operators))
      .run();
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
                    "one_dof_delta_max",
                    "alpha",
                    "one_dof_epsilon",
                    "one_dof_epsilon_overlap",
                    "vibration_fraction",
                    "partner_vibration_fraction",
                    "momentum_error",
                    "one_dof_epsilon_unloading",
                    "ramirez_u"});
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
    table.add(s.schwager_alpha);
    table.add(s.one_dof_epsilon);
    table.add(s.one_dof_epsilon_overlap);
    table.add(s.vibration_fraction);
    table.add(s.partner_vibration_fraction);
    table.add(s.momentum_error);
    table.add(s.one_dof_epsilon_unloading);
    table.add(s.ramirez_u);
    return table;
  }
} // namespace DiskImpact
