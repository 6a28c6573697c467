#pragma once

#include "base/contact_average.h"

#include <deal.II/base/parameter_handler.h>

namespace DiskImpact
{
  /**
   * The generalized-alpha method (Chung & Hulbert, J. Appl. Mech. 60, 1993)
   * for M u'' + D u' + K u + f_c(u) = 0 (D: Kelvin-Voigt damping):
   *
   *   M a_{1-am} + D v_{1-af} + K u_{1-af} + f_bar = 0,
   *   x_{1-a} = (1 - a) x1 + a x0,
   *   u1 = u0 + dt v0 + dt^2 ((1/2 - beta) a0 + beta a1),
   *   v1 = v0 + dt ((1 - gamma) a0 + gamma a1),
   *
   * with am = (2 rho - 1) / (rho + 1), af = rho / (rho + 1), gamma = 1/2 - am
   * + af, beta = (1 - am + af)^2 / 4 from the spectral radius rho at
   * infinite frequency. For the end-of-step displacement u1:
   *
   *   (cm M + cd D + (1 - af) K) u1 + f_bar = M w - D z - af K u0,
   *   cm = (1 - am) / (beta dt^2),   cd = (1 - af) gamma / (beta dt),
   *   w = cm (u0 + dt v0 + dt^2 (1/2 - beta) a0) - am a0,
   *   z = v_{1-af} - cd u1, a combination of u0, v0, a0.
   *
   * rho = 1 is Newmark's average acceleration (the implicit midpoint rule,
   * no numerical dissipation). f_bar is (1 - af) f_c(u1) + af f_c(u0), or,
   * in the scheme 'energy conserving' (rho = 1), the discrete gradient of
   * the contact energy, with which kinetic + strain + contact energy is
   * conserved exactly (docs/theory/impact-method.md). The integrator knows
   * nothing about finite elements: it gives the coefficients and updates
   * vectors.
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
    /// The weight 1 - af of the end-of-step contact force in f_bar.
    double
    contact_new_weight() const;
    /// Whether the contact DoFs carry no inertia (mass redistribution).
    bool
    redistribute_mass() const;
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
    /// The plastic iteration's relative tolerance and iteration limit.
    double
    plastic_tolerance() const;
    unsigned int
    max_plastic_iterations() const;
    /// 'Plastic solver' = Newton (else the fixed point).
    bool
    plastic_newton() const;
    /// Throw an InputError unless a fixed 'Time step' lies within the
    /// range 'Time step fraction' allows, relative to
    /// @p contact_time_estimate.
    void
    check_time_step(double contact_time_estimate) const;
    /// Whether the scheme conserves the total energy (the midpoint rule
    /// with the discrete-gradient contact force).
    bool
    conserves_energy() const;
    /// The relative energy error such a scheme may show ('Energy
    /// tolerance').
    double
    energy_error_tolerance() const;
    /// The same scheme with the time step scaled by @p factor.
    TimeIntegrator
    with_time_step_scaled(double factor) const;

    /// The effective matrix is mass_coefficient M + stiffness_coefficient K.
    double
    mass_coefficient(double dt) const;
    double
    stiffness_coefficient() const;
    /// The weight af of K u0 on the right-hand side M w - D z - af K u0.
    double
    old_stiffness_weight() const;
    /// cd: the effective matrix's coefficient of D.
    double
    damping_coefficient(double dt) const;

    /// z = v_{1-af} - cd u1 (independent of u1).
    template <typename VectorType>
    void
    damping_vector(const VectorType &u0,
                   const VectorType &v0,
                   const VectorType &a0,
                   double            dt,
                   VectorType       &z) const;

    /// v_{1-af} = (1 - af) v1 + af v0: the velocity the damping sees; the
    /// step dissipates dt v_{1-af}^T D v_{1-af}.
    template <typename VectorType>
    void
    damping_velocity(const VectorType &v0,
                     const VectorType &v1,
                     VectorType       &v_mid) const;

    /// w = cm (u0 + dt v0 + dt^2 (1/2 - beta) a0) - am a0.
    template <typename VectorType>
    void
    inertia_vector(const VectorType &u0,
                   const VectorType &v0,
                   const VectorType &a0,
                   double            dt,
                   VectorType       &w) const;

    /// a1 and v1 from the Newmark relations.
    template <typename VectorType>
    void
    update(const VectorType &u0,
           const VectorType &u1,
           const VectorType &v0,
           const VectorType &a0,
           double            dt,
           VectorType       &v1,
           VectorType       &a1) const;

    /// u1 = u0 + dt v0: the predictor of Newton's iteration.
    template <typename VectorType>
    static void
    predictor(const VectorType &u0,
              const VectorType &v0,
              double            dt,
              VectorType       &u1);

  private:
    /// alpha_m, alpha_f, beta, gamma from the spectral radius.
    void
    set_spectral_radius(double rho);

    ContactAverage average             = ContactAverage::discrete_gradient;
    bool           mass_redistribution = false;
    double         fixed_time_step     = 0.;
    double         time_step_fraction  = 0.005;
    double         tolerance           = 1e-13;
    unsigned int   max_iterations      = 30;
    unsigned int   n_step_cuts         = 4;
    double         plastic_tol         = 1e-6;
    unsigned int   max_plastic         = 200;
    bool           newton_plastic      = false;
    double         energy_tolerance    = 1e-6;
    double         alpha_m             = 0.5;
    double         alpha_f             = 0.5;
    double         beta                = 0.25;
    double         gamma               = 0.5;
  };

  template <typename VectorType>
  void
  TimeIntegrator::inertia_vector(const VectorType &u0,
                                 const VectorType &v0,
                                 const VectorType &a0,
                                 const double      dt,
                                 VectorType       &w) const
  {
    const double cm = mass_coefficient(dt);
    w.equ(cm, u0);
    w.add(cm * dt, v0, cm * dt * dt * (0.5 - beta) - alpha_m, a0);
  }

  template <typename VectorType>
  void
  TimeIntegrator::damping_vector(const VectorType &u0,
                                 const VectorType &v0,
                                 const VectorType &a0,
                                 const double      dt,
                                 VectorType       &z) const
  {
    // v1 = g/(b dt) (u1 - u0) + (1 - g/b) v0 + dt (1 - g/(2b)) a0
    const double k = gamma / (beta * dt);
    z              = u0;
    z *= -(1. - alpha_f) * k;
    z.add((1. - alpha_f) * (1. - gamma / beta) + alpha_f,
          v0,
          (1. - alpha_f) * dt * (1. - 0.5 * gamma / beta),
          a0);
  }

  template <typename VectorType>
  void
  TimeIntegrator::damping_velocity(const VectorType &v0,
                                   const VectorType &v1,
                                   VectorType       &v_mid) const
  {
    v_mid = v1;
    v_mid *= 1. - alpha_f;
    v_mid.add(alpha_f, v0);
  }

  template <typename VectorType>
  void
  TimeIntegrator::update(const VectorType &u0,
                         const VectorType &u1,
                         const VectorType &v0,
                         const VectorType &a0,
                         const double      dt,
                         VectorType       &v1,
                         VectorType       &a1) const
  {
    const double k = 1. / (beta * dt * dt);
    a1.equ(k, u1);
    a1.add(-k, u0, -k * dt, v0);
    a1.add(-k * dt * dt * (0.5 - beta), a0);
    v1 = v0;
    v1.add(dt * (1. - gamma), a0, dt * gamma, a1);
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
