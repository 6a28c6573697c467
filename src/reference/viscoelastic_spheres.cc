#include "reference/viscoelastic_spheres.h"

#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/tools/rational.hpp>

#include <cmath>

namespace DiskImpact
{
  namespace Reference
  {
    ForceLaw
    hertz_force_law(const double rho)
    {
      return {[=](const double xi) {
                return xi > 0. ? rho * xi * std::sqrt(xi) : 0.;
              },
              [=](const double xi) {
                return xi > 0. ? 1.5 * rho * std::sqrt(xi) : 0.;
              }};
    }

    double
    sphere_c1()
    {
      using boost::math::tgamma;
      return std::sqrt(M_PI) * tgamma(0.6) /
             (std::pow(2., 0.2) * std::pow(5., 0.4) * tgamma(2.1));
    }

    double
    sphere_characteristic_velocity(const double effective_mass,
                                   const double rho,
                                   const double dissipation)
    {
      return std::pow(
        sphere_scaled_velocity(effective_mass, rho, dissipation, 1.), -5.);
    }

    double
    sphere_scaled_velocity(const double effective_mass,
                           const double rho,
                           const double dissipation,
                           const double velocity)
    {
      return sphere_c1() * 1.5 * dissipation *
             std::pow(rho / effective_mass, 0.4) * std::pow(velocity, 0.2);
    }

    double
    sphere_delayed_recovery_coefficient()
    {
      return 4. / 15. * std::pow(sphere_c1(), -2.5);
    }

    double
    sphere_restitution_series(const double                    scaled_velocity,
                              const EndCriterion              end,
                              const SphereSeriesCoefficients &coefficients)
    {
      const double u        = scaled_velocity;
      const double series[] = {1.,
                               -coefficients.a1,
                               coefficients.a2,
                               -coefficients.a3,
                               coefficients.a4};
      const double epsilon = boost::math::tools::evaluate_polynomial(series, u);
      if (end == EndCriterion::overlap)
        return epsilon;
      return epsilon + sphere_delayed_recovery_coefficient() * u * u *
                         std::sqrt(u) * (1. - 1.5 * u);
    }

    SpherePadeCoefficients
    sphere_pade_coefficients(const SphereSeriesCoefficients &coefficients)
    {
      const double a2 = coefficients.a2, a3 = coefficients.a3,
                   a4 = coefficients.a4;
      const double d0 = a4 - 2. * a3 - a2 * a2 + 3. * a2 - 1.;
      return {(1. - a2 + a3 - 2. * a4 + (a2 - 1.) * (3. * a2 - 2. * a3)) / d0,
              ((a3 - a2) * (1. - 2. * a2) - a4) / d0,
              (a3 + a2 * a2 * (a2 - 1.) - a4 * (a2 + 1.)) / d0,
              (a4 * (a3 - 1.) + (a3 - a2) * (a2 * a2 - 2. * a3)) / d0,
              (2. * (a3 - a2) * (a4 - a2 * a3) -
               (a4 - a2 * a2) * (a4 - a2 * a2) - a3 * (a3 - a2 * a2)) /
                d0};
    }

    double
    sphere_restitution_pade(const double                    scaled_velocity,
                            const SphereSeriesCoefficients &coefficients)
    {
      const auto   d             = sphere_pade_coefficients(coefficients);
      const double numerator[]   = {1., d.d1, 0., 0., 0.};
      const double denominator[] = {1., d.d2, d.d3, d.d4, d.d5};
      return boost::math::tools::evaluate_rational(numerator,
                                                   denominator,
                                                   scaled_velocity);
    }

    double
    sphere_restitution_ode(const double       scaled_velocity,
                           const EndCriterion end,
                           const double       tolerance)
    {
      const double dissipation = scaled_velocity / (1.5 * sphere_c1());
      return collide(1., 1., hertz_force_law(1.), dissipation, end, tolerance)
        .epsilon;
    }
  } // namespace Reference
} // namespace DiskImpact
