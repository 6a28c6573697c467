#include "run/impact_parameters.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "base/renamed_entries.h"
#include "reference/log_contact_law.h"

#include <deal.II/base/utilities.h>

#include <algorithm>
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
  ImpactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact");
    prm.declare_entry("Velocity",
                      "0.01",
                      Patterns::Double(),
                      "Impact speed v_i in units of c = sqrt(E2 / rho) [-], "
                      "0 < v_i <= 0.5; with a partner body (subsection "
                      "Partner) the relative speed, 0 < v_i <= 1. With an "
                      "'Angle of incidence' theta the body approaches the "
                      "wall at v_i cos(theta) and moves along it at "
                      "v_i sin(theta).");
    prm.declare_entry("Angle of incidence",
                      "0",
                      Patterns::Double(0., 89.),
                      "Angle between the centre of mass's velocity before "
                      "the impact and the wall's normal [degrees]; 0: "
                      "head-on. The tangential velocity points along the "
                      "wall's tangent (-n_y, n_x). An oblique impact needs "
                      "the whole disk (Domain = full disk).");
    prm.declare_entry("Spin",
                      "0",
                      Patterns::Double(),
                      "The body's angular velocity before the impact about "
                      "e_z, counterclockwise positive, in units of c / R "
                      "[-] (rad/s in SI): omega R is the rim's speed. Needs "
                      "the whole disk (Domain = full disk).");
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
    prm.declare_entry("Graded mesh",
                      "hanging nodes",
                      Patterns::Selection("hanging nodes|conforming"),
                      "'hanging nodes': the mesh is refined toward the "
                      "contact (a disk in 3D in all three directions, its "
                      "cells about cubes). 'conforming': the mesh is graded "
                      "with half the elements across the contact and twice "
                      "the grading, then every element is halved so that no "
                      "hanging nodes remain (the same sizes; a cell with "
                      "hanging nodes becomes a fan of small quadrilaterals). "
                      "A disk in 3D extrudes this section through layers "
                      "graded toward its faces like the section toward the "
                      "contact, so its elements along the contact line are "
                      "long in z: far fewer cells at low speeds. One body "
                      "against the wall, a disk or the sphere's meridian; "
                      "'Elements across contact' even.");
    prm.declare_entry("Layer refinement",
                      "0",
                      Patterns::Integer(-2, 2),
                      "A disk in 3D with 'Graded mesh = conforming': its "
                      "layers through the thickness graded as for a section "
                      "refined this many times more (2^k times the elements "
                      "across, the grading and the largest layer over 2^k; "
                      "k < 0 coarser), the section unchanged. A convergence "
                      "level whose whole refinement exceeds the memory can "
                      "so be run in two parts: the section and the time step "
                      "refined (one level more in 'Global refinements', "
                      "'Elements across contact', 'Grading' and 'Time step "
                      "fraction') with k = -1, and the layers alone, k = 1 "
                      "(bench/free_disk_restitution.sh) [-]; 0: the "
                      "section's.");
    prm.declare_entry("Graded half-width",
                      "0",
                      Patterns::Double(0., 1.),
                      "Half-width of the contact zone the mesh is graded for "
                      "[R]; 0: Hertz's half-width at the 1-DOF model's "
                      "largest force at this speed. A fixed value keeps one "
                      "mesh for every speed of a sweep (epsilon(v) on one "
                      "discretization).");
    prm.declare_entry("Grade for measured contact",
                      "false",
                      Patterns::Bool(),
                      "true: a first impact on the mesh graded for Hertz's "
                      "half-width measures the contact's largest half-width "
                      "a_max, and the impact (every level of its convergence "
                      "study) runs on a mesh graded for a_max with the same "
                      "element size at the contact ('Elements across "
                      "contact' times a_max over Hertz's half-width, even). "
                      "For plastic impacts, whose contact grows wider than "
                      "Hertz's (about 1.5 times at 100 v_y); not with "
                      "'Graded half-width'.");
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
    prm.declare_entry("Angles of incidence",
                      "",
                      Patterns::List(Patterns::Double(0., 89.), 0),
                      "Task 'sweep': angles of incidence (as 'Angle of "
                      "incidence') [degrees]; empty: 'Angle of incidence'.");
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
  ImpactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impact");
    impact_velocity        = prm.get_double("Velocity");
    incidence_angle        = prm.get_double("Angle of incidence");
    initial_spin           = prm.get_double("Spin");
    contact_elements       = prm.get_integer("Elements across contact");
    mesh_grading           = prm.get_double("Grading");
    fine_zone              = prm.get_double("Fine zone radius");
    fixed_half_width       = prm.get_double("Graded half-width");
    measured_grading       = prm.get_bool("Grade for measured contact");
    conforming             = prm.get("Graded mesh") == "conforming";
    layer_levels           = prm.get_integer("Layer refinement");
    law_constant           = prm.get("One-DOF law constant");
    margin                 = prm.get_double("Time after contact");
    output_interval        = prm.get_integer("Output interval");
    revolved_view_angle    = prm.get_double("Revolved view");
    projected_modes        = prm.get_integer("Number of projected modes");
    sweep_velocities       = get_double_list(prm, "Velocities");
    sweep_poisson_ratios   = get_double_list(prm, "Poisson ratios");
    sweep_angles           = get_double_list(prm, "Angles of incidence");
    sweep_relaxation_times = get_double_list(prm, "Relaxation times");
    sweep_partner_radii    = get_double_list(prm, "Partner radii");
    error_estimate         = prm.get_bool("Convergence study per point");
    resume_sweep           = prm.get_bool("Resume");
    prm.leave_subsection();
    check_velocities(1.);
    require(!measured_grading || fixed_half_width == 0.,
            "Impact: 'Grade for measured contact' grades the mesh for the "
            "measured half-width, 'Graded half-width' for a given one; set "
            "one of them");
    require(!conforming || contact_elements % 2 == 0,
            "Impact: 'Graded mesh = conforming' halves a mesh with half of "
            "'Elements across contact', which must be even, got " +
              std::to_string(contact_elements));
    if (!finite_size_law_constant())
      fixed_law_constant(0., false);
  }

  void
  ImpactParameters::check_velocities(const double largest) const
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
  ImpactParameters::velocity() const
  {
    return impact_velocity;
  }

  double
  ImpactParameters::normal_velocity() const
  {
    return impact_velocity * std::cos(incidence_angle * M_PI / 180.);
  }

  double
  ImpactParameters::tangential_velocity() const
  {
    return impact_velocity * std::sin(incidence_angle * M_PI / 180.);
  }

  void
  ImpactParameters::set_velocity(const double v)
  {
    impact_velocity = v;
  }

  const std::vector<double> &
  ImpactParameters::velocities() const
  {
    return sweep_velocities;
  }

  const std::vector<double> &
  ImpactParameters::incidence_angles() const
  {
    return sweep_angles;
  }

  bool
  ImpactParameters::is_oblique() const
  {
    return incidence_angle != 0. || initial_spin != 0. ||
           std::any_of(sweep_angles.begin(),
                       sweep_angles.end(),
                       [](const double angle) { return angle != 0.; });
  }

  const std::vector<double> &
  ImpactParameters::poisson_ratios() const
  {
    return sweep_poisson_ratios;
  }

  const std::vector<double> &
  ImpactParameters::relaxation_times() const
  {
    return sweep_relaxation_times;
  }

  const std::vector<double> &
  ImpactParameters::partner_radii() const
  {
    return sweep_partner_radii;
  }

  bool
  ImpactParameters::estimate_errors() const
  {
    return error_estimate;
  }

  bool
  ImpactParameters::resume() const
  {
    return resume_sweep;
  }

  ImpactParameters
  ImpactParameters::with_mesh_refined(const unsigned int levels) const
  {
    ImpactParameters finer = *this;
    finer.contact_elements = contact_elements << levels;
    finer.mesh_grading     = mesh_grading / (1u << levels);
    return finer;
  }

  ImpactParameters
  ImpactParameters::with_mesh_coarsened() const
  {
    ImpactParameters coarser = *this;
    coarser.contact_elements = contact_elements / 2;
    coarser.mesh_grading     = 2. * mesh_grading;
    return coarser;
  }

  ImpactParameters
  ImpactParameters::with_mesh_graded_for(const double       half_width,
                                         const unsigned int elements,
                                         const double       grading,
                                         const bool conforming_mesh) const
  {
    ImpactParameters graded = *this;
    graded.fixed_half_width = half_width;
    graded.measured_grading = false;
    graded.contact_elements = elements;
    graded.mesh_grading     = grading;
    graded.conforming       = conforming_mesh;
    return graded;
  }

  double
  ImpactParameters::fixed_law_constant(const double nu2,
                                       const bool   sphere) const
  {
    return parse_contact_law_constant(law_constant, nu2, sphere);
  }
} // namespace DiskImpact
