#pragma once

#include "contact/contact_law.h"

namespace DiskImpact
{
  /**
   * 'Law = exponential': the smooth wall potential of Gerl & Zippelius 1999
   * (eq. 41), energy (E2 / lambda) exp(lambda x) per unit length with x the
   * distance of the point beyond the wall plane and lambda = s / R (s the
   * 'Potential stiffness'), cut where its pressure E2 exp(lambda x) falls
   * below p_c = 1e-16 E2: the law's plane g = 0 lies ln(E2 / p_c) / lambda
   * in front of the wall plane, p = p_c exp(-lambda g) and energy
   * (p_c / lambda)(exp(-lambda g) - 1) for g < 0, both zero for g >= 0
   * (the energy is continuous; the pressure jumps by p_c). A soft wall of
   * its own, not a regularization of hard contact.
   */
  class ExponentialLaw : public ContactLaw
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm) override;
    std::unique_ptr<ContactLaw>
    clone() const override;
    void
    set_scales(const ContactScales &scales) override;
    bool
    approximates_hard_contact() const override;

    double
    pressure(double gap) const override;
    double
    pressure_derivative(double gap) const override;
    double
    energy(double gap) const override;
    /// ln(E2 / p_c) / lambda: the wall plane's distance from the law's.
    double
    reach() const override;
    /// Both gaps negative: p(g0) phi(lambda (g1 - g0)) without cancellation,
    /// phi(x) = (1 - e^-x) / x.
    double
    discrete_gradient_pressure(double g0, double g1) const override;
    double
    discrete_gradient_derivative(double g0, double g1) const override;

    /// For a law set up directly: lambda [1 / length] and p_c [pressure].
    void
    set(double decay, double threshold);

  private:
    double alpha     = 100.; ///< 'Potential stiffness' s
    double decay     = 0.;   ///< lambda = s / R
    double threshold = 0.;   ///< p_c
  };
} // namespace DiskImpact
