#pragma once

#include "contact/contact_law.h"

namespace DiskImpact
{
  /**
   * 'Law = penalty': p = k <-g> (<.> the positive part), energy
   * k <-g>^2 / 2, with the stiffness k = kappa E2 / h from the dimensionless
   * 'Penalty factor' kappa and the smallest edge face h at the contact
   * point. The penetration, the law's error against hard contact, is
   * proportional to 1 / kappa.
   */
  class PenaltyLaw : public ContactLaw
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
    /// kappa times @p factor.
    void
    stiffen(double factor) override;

    double
    pressure(double gap) const override;
    double
    pressure_derivative(double gap) const override;
    double
    energy(double gap) const override;
    /// k: the stick is as stiff as the wall.
    double
    tangential_stiffness() const override;
    bool
    supports_friction() const override;

    double
    penalty_factor() const;

  private:
    double kappa = 100.;
    double k     = 0.;
  };
} // namespace DiskImpact
