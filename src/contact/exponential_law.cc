#include "contact/exponential_law.h"

#include "base/input_error.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <utility>

namespace DiskImpact
{
  using namespace dealii;

  DISKIMPACT_REGISTER_CONTACT_LAW(
    ExponentialLaw,
    "exponential",
    "the smooth wall potential of Gerl & Zippelius 1999 (eq. 41), energy "
    "(E2 R / s) exp(s x / R) per unit edge length, s the 'Potential "
    "stiffness' and x the distance of the point beyond the wall plane, cut "
    "where the pressure falls below 1e-16 E2 (the disk starts that far from "
    "the wall, 36.8 R / s)")

  namespace
  {
    /// p_c / E2: below it the pressure is dropped.
    constexpr double exponential_cut = 1e-16;

    /// phi(x) = (1 - e^{-x}) / x and phi'(x), accurate near x = 0.
    std::pair<double, double>
    relative_secant(const double x)
    {
      if (std::abs(x) < 1e-3)
        return {1. - x / 2. + x * x / 6. - x * x * x / 24.,
                -0.5 + x / 3. - x * x / 8. + x * x * x / 30.};
      const double e = std::exp(-x);
      return {-std::expm1(-x) / x, ((1. + x) * e - 1.) / (x * x)};
    }
  } // namespace

  void
  ExponentialLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Potential stiffness",
                      "100",
                      Patterns::Double(),
                      "Law 'exponential': the stiffness s > 0 of the "
                      "potential [-] (Gerl & Zippelius' alpha; hard contact "
                      "as s -> infinity).");
  }

  void
  ExponentialLaw::parse_parameters(ParameterHandler &prm)
  {
    alpha = prm.get_double("Potential stiffness");
    require(alpha > 0.,
            "Contact: 'Potential stiffness' must be positive, got " +
              Utilities::to_string(alpha));
  }

  std::unique_ptr<ContactLaw>
  ExponentialLaw::clone() const
  {
    return std::make_unique<ExponentialLaw>(*this);
  }

  void
  ExponentialLaw::set_scales(const ContactScales &scales)
  {
    set(alpha / scales.radius, exponential_cut * scales.modulus);
  }

  void
  ExponentialLaw::set(const double lambda, const double p_c)
  {
    decay     = lambda;
    threshold = p_c;
  }

  bool
  ExponentialLaw::approximates_hard_contact() const
  {
    return false;
  }

  double
  ExponentialLaw::pressure(const double gap) const
  {
    return gap < 0. ? threshold * std::exp(-decay * gap) : 0.;
  }

  double
  ExponentialLaw::pressure_derivative(const double gap) const
  {
    return gap < 0. ? -decay * pressure(gap) : 0.;
  }

  double
  ExponentialLaw::energy(const double gap) const
  {
    return gap < 0. ? threshold / decay * std::expm1(-decay * gap) : 0.;
  }

  double
  ExponentialLaw::reach() const
  {
    return -std::log(exponential_cut) / decay;
  }

  double
  ExponentialLaw::discrete_gradient_pressure(const double g0,
                                             const double g1) const
  {
    if (g0 < 0. && g1 < 0.)
      return pressure(g0) * relative_secant(decay * (g1 - g0)).first;
    return ContactLaw::discrete_gradient_pressure(g0, g1);
  }

  double
  ExponentialLaw::discrete_gradient_derivative(const double g0,
                                               const double g1) const
  {
    if (g0 < 0. && g1 < 0.)
      return pressure(g0) * decay * relative_secant(decay * (g1 - g0)).second;
    return ContactLaw::discrete_gradient_derivative(g0, g1);
  }
} // namespace DiskImpact
