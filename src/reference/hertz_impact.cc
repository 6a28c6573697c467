#include "reference/hertz_impact.h"

#include <cmath>
#include <stdexcept>

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
  } // namespace Reference
} // namespace DiskImpact
