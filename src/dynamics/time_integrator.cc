#include "dynamics/time_integrator.h"

#include "base/input_error.h"

namespace DiskImpact
{
  using namespace dealii;

  void
  TimeIntegrator::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    prm.declare_entry(
      "Scheme",
      "energy conserving",
      Patterns::Selection("energy conserving|newmark|generalized alpha"),
      "'newmark': average acceleration (no numerical dissipation) with the "
      "trapezoidal contact force; 'energy conserving': the same with the "
      "contact force as the discrete gradient of the contact energy, which "
      "conserves the total energy exactly; 'generalized alpha': "
      "Chung-Hulbert with 'Spectral radius', damping the highest "
      "frequencies.");
    prm.declare_entry("Spectral radius",
                      "0.8",
                      Patterns::Double(0., 1.),
                      "Scheme 'generalized alpha': the amplification factor "
                      "rho_inf at infinite frequency, 0 <= rho_inf <= 1 "
                      "(1: no numerical dissipation) [-].");
    prm.declare_entry("Contact mass",
                      "consistent",
                      Patterns::Selection("consistent|redistributed"),
                      "'redistributed': the DoFs of the edge that can touch "
                      "the wall carry no inertia (mass redistribution), so "
                      "the stiff penalty contact cannot make them chatter; "
                      "'consistent': the plain mass matrix.");
    prm.declare_entry("Time step",
                      "0",
                      Patterns::Double(0.),
                      "Time step [time]; 0: 'Time step fraction' times the "
                      "contact time estimated by the 1-DOF log law.");
    prm.declare_entry("Time step fraction",
                      "0.005",
                      Patterns::Double(1e-6, 0.5),
                      "Time step as a fraction of the estimated contact time "
                      "[-] (used when 'Time step' is 0).");
    prm.declare_entry("Newton tolerance",
                      "1e-13",
                      Patterns::Double(1e-16, 1e-3),
                      "Newton stops when the residual of the contact DoFs' "
                      "displacements, |u_C - y_C - S P(u_C)|_inf, is at most "
                      "this times the largest approach the 1-DOF model "
                      "expects [-].");
    prm.declare_entry("Maximum Newton iterations",
                      "30",
                      Patterns::Integer(1, 1000),
                      "Newton iterations per step before the step is cut "
                      "(ten times as many under friction, whose stick-slip "
                      "kinks shorten Newton's steps).");
    prm.declare_entry("Energy tolerance",
                      "1e-6",
                      Patterns::Double(0.),
                      "Scheme 'energy conserving': the largest change of the "
                      "total energy (kinetic + strain + contact + "
                      "dissipated), relative to the initial energy, that a "
                      "run may show; more ends the run with an error (the "
                      "balance is its accuracy check). Every scheme: the "
                      "largest growth of the total energy (energy created "
                      "by an unstable step) [-].");
    prm.declare_entry("Plastic tolerance",
                      "1e-6",
                      Patterns::Double(1e-15, 1e-2),
                      "Elastic-plastic bodies: a step's plastic iteration "
                      "stops when the plastic strain's force changes by at "
                      "most this times its size (l2 norms) [-].");
    prm.declare_entry("Plastic solver",
                      "fixed point",
                      Patterns::Selection("fixed point|Newton"),
                      "Elastic-plastic bodies: how a step finds its plastic "
                      "strains. 'fixed point': with the elastic "
                      "factorization throughout, the plastic strain's force "
                      "iterated by Anderson's acceleration. 'Newton': while "
                      "points yield, the effective matrix with the "
                      "consistent plastic tangent, factorized again (with "
                      "its contact columns) when the set of yielding points "
                      "changes or an iteration stalls; the elastic "
                      "factorization while none yields. Newton takes fewer "
                      "iterations, but each new tangent costs a "
                      "factorization and a solve per contact DoF, so the "
                      "fixed point is the faster on the meshes of "
                      "docs/guide/plastic-impacts.md.");
    prm.declare_entry("Maximum plastic iterations",
                      "200",
                      Patterns::Integer(1, 10000),
                      "Elastic-plastic bodies: plastic iterations per step "
                      "before the step is cut.");
    prm.declare_entry("Maximum step cuts",
                      "4",
                      Patterns::Integer(0, 20),
                      "How often the time step may be halved after a Newton "
                      "failure before the run stops with an error.");
    prm.leave_subsection();
  }

  void
  TimeIntegrator::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    const std::string scheme = prm.get("Scheme");
    average                  = scheme == "energy conserving" ?
                                 ContactAverage::discrete_gradient :
                                 ContactAverage::trapezoidal;
    set_spectral_radius(
      scheme == "generalized alpha" ? prm.get_double("Spectral radius") : 1.);
    mass_redistribution = prm.get("Contact mass") == "redistributed";
    fixed_time_step     = prm.get_double("Time step");
    time_step_fraction  = prm.get_double("Time step fraction");
    tolerance           = prm.get_double("Newton tolerance");
    max_iterations      = prm.get_integer("Maximum Newton iterations");
    n_step_cuts         = prm.get_integer("Maximum step cuts");
    plastic_tol         = prm.get_double("Plastic tolerance");
    max_plastic         = prm.get_integer("Maximum plastic iterations");
    newton_plastic      = prm.get("Plastic solver") == "Newton";
    energy_tolerance    = prm.get_double("Energy tolerance");
    prm.leave_subsection();
  }

  ContactAverage
  TimeIntegrator::contact_average() const
  {
    return average;
  }

  double
  TimeIntegrator::time_step(const double contact_time_estimate) const
  {
    return fixed_time_step > 0. ? fixed_time_step :
                                  time_step_fraction * contact_time_estimate;
  }

  double
  TimeIntegrator::newton_tolerance() const
  {
    return tolerance;
  }

  unsigned int
  TimeIntegrator::max_newton_iterations() const
  {
    return max_iterations;
  }

  double
  TimeIntegrator::plastic_tolerance() const
  {
    return plastic_tol;
  }

  bool
  TimeIntegrator::plastic_newton() const
  {
    return newton_plastic;
  }

  unsigned int
  TimeIntegrator::max_plastic_iterations() const
  {
    return max_plastic;
  }

  unsigned int
  TimeIntegrator::max_step_cuts() const
  {
    return n_step_cuts;
  }

  TimeIntegrator
  TimeIntegrator::with_time_step_scaled(const double factor) const
  {
    TimeIntegrator scaled = *this;
    scaled.fixed_time_step *= factor;
    scaled.time_step_fraction *= factor;
    return scaled;
  }

  void
  TimeIntegrator::set_spectral_radius(const double rho)
  {
    alpha_m = (2. * rho - 1.) / (rho + 1.);
    alpha_f = rho / (rho + 1.);
    gamma   = 0.5 - alpha_m + alpha_f;
    beta    = 0.25 * (1. - alpha_m + alpha_f) * (1. - alpha_m + alpha_f);
  }

  double
  TimeIntegrator::contact_new_weight() const
  {
    return 1. - alpha_f;
  }

  bool
  TimeIntegrator::redistribute_mass() const
  {
    return mass_redistribution;
  }

  double
  TimeIntegrator::mass_coefficient(const double dt) const
  {
    return (1. - alpha_m) / (beta * dt * dt);
  }

  double
  TimeIntegrator::stiffness_coefficient() const
  {
    return 1. - alpha_f;
  }

  double
  TimeIntegrator::old_stiffness_weight() const
  {
    return alpha_f;
  }

  double
  TimeIntegrator::damping_coefficient(const double dt) const
  {
    return (1. - alpha_f) * gamma / (beta * dt);
  }

  bool
  TimeIntegrator::conserves_energy() const
  {
    return average == ContactAverage::discrete_gradient && alpha_f == 0.5 &&
           alpha_m == 0.5;
  }

  double
  TimeIntegrator::energy_error_tolerance() const
  {
    return energy_tolerance;
  }

  void
  TimeIntegrator::check_time_step(const double contact_time_estimate) const
  {
    if (fixed_time_step > 0.)
      require(fixed_time_step >= 1e-6 * contact_time_estimate &&
                fixed_time_step <= 0.5 * contact_time_estimate,
              "Time stepping: 'Time step' = " + approximately(fixed_time_step) +
                " must lie between 1e-6 and 0.5 times the contact time the "
                "1-DOF model expects, " +
                approximately(contact_time_estimate, 4) +
                " (as 'Time step fraction' does)");
  }
} // namespace DiskImpact
