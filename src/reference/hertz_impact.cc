#include "reference/hertz_impact.h"

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace DiskImpact
{
  namespace Reference
  {
    double
    hertz_sphere_stiffness(const double effective_modulus, const double radius)
    {
      return 4. / 3. * effective_modulus * std::sqrt(radius);
    }

    HertzImpact
    hertz_sphere_impact(const double mass,
                        const double effective_modulus,
                        const double radius,
                        const double velocity)
    {
      if (!(mass > 0.) || !(effective_modulus > 0.) || !(radius > 0.) ||
          !(velocity > 0.))
        throw std::invalid_argument(
          "hertz_sphere_impact: mass, modulus, radius and velocity must be "
          "positive");
      const double rho = hertz_sphere_stiffness(effective_modulus, radius);
      HertzImpact  impact;
      impact.max_overlap =
        std::pow(1.25 * mass * velocity * velocity / rho, 0.4);
      // (2/5) B(2/5, 1/2) = (2/5) Gamma(2/5) Gamma(1/2) / Gamma(9/10)
      const double quarter_period_integral =
        0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
      impact.contact_time =
        2. * quarter_period_integral * impact.max_overlap / velocity;
      impact.max_force = rho * std::pow(impact.max_overlap, 1.5);
      return impact;
    }

    namespace
    {
      /// d(x) = (3 pi x / 4)^{2/3} + pi D x and its derivative.
      struct FiniteSphereLaw
      {
        double D;

        double
        approach(const double x) const
        {
          return std::pow(0.75 * M_PI * x, 2. / 3.) + M_PI * D * x;
        }
        double
        slope(const double x) const
        {
          return 2. / 3. * std::pow(0.75 * M_PI, 2. / 3.) / std::cbrt(x) +
                 M_PI * D;
        }
        /// The load at which d(x) is largest (infinite for D >= 0).
        double
        largest_load() const
        {
          return D >= 0. ? std::numeric_limits<double>::infinity() :
                           std::pow(2. / 3. * std::pow(0.75 * M_PI, 2. / 3.) /
                                      (-M_PI * D),
                                    3.);
        }
        /// x(d) on the rising branch, bracketed by Hertz's 4 d^{3/2} / (3 pi)
        /// and the largest load.
        double
        load(const double d) const
        {
          const double x_hertz = 4. * std::pow(d, 1.5) / (3. * M_PI);
          if (D == 0.)
            return x_hertz;
          const double x_top = largest_load();
          if (D < 0. && !(d < approach(x_top)))
            throw std::domain_error(
              "sphere_force_law: the approach exceeds the finite-size law's "
              "largest, " +
              std::to_string(approach(x_top)) + " R");
          const double   lower      = D > 0. ? 0. : x_hertz;
          const double   upper      = D > 0. ? x_hertz : x_top;
          std::uintmax_t iterations = 200;
          const auto     root       = boost::math::tools::toms748_solve(
            [&](const double x) { return approach(x) - d; },
            lower,
            upper,
            boost::math::tools::eps_tolerance<double>(52),
            iterations);
          return 0.5 * (root.first + root.second);
        }
      };
    } // namespace

    ForceLaw
    sphere_force_law(const double effective_modulus,
                     const double radius,
                     const double finite_size_constant)
    {
      const FiniteSphereLaw law{finite_size_constant};
      const double          unit = M_PI * effective_modulus * radius * radius;
      return {[=](const double xi) {
                return xi > 0. ? unit * law.load(xi / radius) : 0.;
              },
              [=](const double xi) {
                return xi > 0. ?
                         unit / (radius * law.slope(law.load(xi / radius))) :
                         0.;
              }};
    }
  } // namespace Reference
} // namespace DiskImpact
