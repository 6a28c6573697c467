#pragma once

#include "contact_operator.h"

#include <deal.II/base/parameter_handler.h>

namespace DiskImpact
{
  /**
   * Newmark's average-acceleration rule (beta = 1/4, gamma = 1/2), written
   * as the implicit midpoint rule for M u'' + K u + f_c(u) = 0:
   *
   *   M (v1 - v0) / dt = -K (u0 + u1) / 2 - f_bar,   (u1 - u0) / dt = (v0 + v1)
   * / 2,
   *
   * i.e. for the end-of-step displacement
   *
   *   (2/dt^2 M + K/2) u1 + f_bar = M (2/dt^2 u0 + 2/dt v0) - K u0 / 2.
   *
   * f_bar is the contact force of the step: trapezoidal (plain Newmark) or
   * the discrete gradient of the contact energy, with which kinetic + strain
   * + contact energy is conserved exactly (docs/impact.md). The integrator
   * knows nothing about finite elements: it gives the coefficients and
   * updates vectors.
   */
  class TimeIntegrator
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    ContactAverage
    contact_average() const;
    /// The step: 'Time step' if positive, else 'Time step fraction' times
    /// @p contact_time_estimate.
    double
    time_step(double contact_time_estimate) const;
    double
    newton_tolerance() const;
    unsigned int
    max_newton_iterations() const;
    unsigned int
    max_step_cuts() const;
    /// The same scheme with half the time step.
    TimeIntegrator
    refined() const;

    /// A = mass_coefficient M + stiffness_coefficient K.
    static double
    mass_coefficient(double dt);
    static double
    stiffness_coefficient();

    /// w = 2/dt^2 u0 + 2/dt v0; the right-hand side is M w - K u0 / 2.
    template <typename VectorType>
    static void
    inertia_vector(const VectorType &u0,
                   const VectorType &v0,
                   double            dt,
                   VectorType       &w);

    /// v1 = 2 (u1 - u0) / dt - v0.
    template <typename VectorType>
    static void
    velocity_update(const VectorType &u0,
                    const VectorType &u1,
                    const VectorType &v0,
                    double            dt,
                    VectorType       &v1);

    /// u1 = u0 + dt v0: the predictor of Newton's iteration.
    template <typename VectorType>
    static void
    predictor(const VectorType &u0,
              const VectorType &v0,
              double            dt,
              VectorType       &u1);

  private:
    ContactAverage average            = ContactAverage::discrete_gradient;
    double         fixed_time_step    = 0.;
    double         time_step_fraction = 0.005;
    double         tolerance          = 1e-11;
    unsigned int   max_iterations     = 30;
    unsigned int   n_step_cuts        = 4;
  };

  template <typename VectorType>
  void
  TimeIntegrator::inertia_vector(const VectorType &u0,
                                 const VectorType &v0,
                                 const double      dt,
                                 VectorType       &w)
  {
    w = u0;
    w *= 2. / (dt * dt);
    w.add(2. / dt, v0);
  }

  template <typename VectorType>
  void
  TimeIntegrator::velocity_update(const VectorType &u0,
                                  const VectorType &u1,
                                  const VectorType &v0,
                                  const double      dt,
                                  VectorType       &v1)
  {
    v1 = u1;
    v1.add(-1., u0);
    v1 *= 2. / dt;
    v1.add(-1., v0);
  }

  template <typename VectorType>
  void
  TimeIntegrator::predictor(const VectorType &u0,
                            const VectorType &v0,
                            const double      dt,
                            VectorType       &u1)
  {
    u1 = u0;
    u1.add(dt, v0);
  }
} // namespace DiskImpact
