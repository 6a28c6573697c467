#include "time_integrator.h"

#include "input_error.h"

namespace DiskImpact
{
  using namespace dealii;

  void
  TimeIntegrator::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    prm.declare_entry("Scheme",
                      "energy conserving",
                      Patterns::Selection("energy conserving|newmark"),
                      "'newmark': average acceleration with the trapezoidal "
                      "contact force; 'energy conserving': the same with the "
                      "contact force as the discrete gradient of the contact "
                      "energy, which conserves the total energy exactly.");
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
                      "1e-11",
                      Patterns::Double(1e-16, 1e-3),
                      "Newton stops when |residual| <= this times the "
                      "inertial force 2 |M v0| / dt [-].");
    prm.declare_entry("Maximum Newton iterations",
                      "30",
                      Patterns::Integer(1, 1000),
                      "Newton iterations per step before the step is cut.");
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
    average            = prm.get("Scheme") == "newmark" ?
                           ContactAverage::trapezoidal :
                           ContactAverage::discrete_gradient;
    fixed_time_step    = prm.get_double("Time step");
    time_step_fraction = prm.get_double("Time step fraction");
    tolerance          = prm.get_double("Newton tolerance");
    max_iterations     = prm.get_integer("Maximum Newton iterations");
    n_step_cuts        = prm.get_integer("Maximum step cuts");
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

  unsigned int
  TimeIntegrator::max_step_cuts() const
  {
    return n_step_cuts;
  }

  TimeIntegrator
  TimeIntegrator::refined() const
  {
    TimeIntegrator finer = *this;
    finer.fixed_time_step *= 0.5;
    finer.time_step_fraction *= 0.5;
    return finer;
  }

  double
  TimeIntegrator::mass_coefficient(const double dt)
  {
    return 2. / (dt * dt);
  }

  double
  TimeIntegrator::stiffness_coefficient()
  {
    return 0.5;
  }
} // namespace DiskImpact
