#include "reference/one_dof_impact.h"

#include "reference/log_contact_law.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    OneDofImpact
    one_dof_impact(const double velocity,
                   const double mass,
                   const double E2,
                   const double R,
                   const double constant)
    {
      using boost::math::quadrature::gauss_kronrod;
      const LogContactLaw law(constant);
      auto                force = [&](const double delta) {
        return delta <= 0. ? 0. : M_PI * E2 * R * law.load(delta / R);
      };
      auto potential = [&](const double delta) {
        return gauss_kronrod<double, 31>::integrate(force, 0., delta, 5, 1e-12);
      };
      const double energy = 0.5 * mass * velocity * velocity;
      const double limit  = 0.999 * law.maximum_compression() * R;
      if (!(potential(limit) > energy))
        throw std::domain_error(
          "one_dof_impact: the velocity is too high for the log law");

      boost::uintmax_t iterations = 200;
      const auto       bracket    = boost::math::tools::toms748_solve(
        [&](const double d) { return potential(d) - energy; },
        0.,
        limit,
        boost::math::tools::eps_tolerance<double>(50),
        iterations);
      OneDofImpact result;
      result.max_compression = 0.5 * (bracket.first + bracket.second);
      result.max_force       = force(result.max_compression);

      // With delta = delta_max (1 - s^2) the turning point's inverse square
      // root becomes finite: d delta = 2 delta_max s ds and
      // v^2 - 2 V(delta)/m = 2/m int_delta^delta_max P ~ s^2.
      const double delta_max = result.max_compression;
      auto         integrand = [&](const double s) {
        if (s <= 0.)
          return 2. * delta_max /
                 std::sqrt(2. * result.max_force * delta_max / mass);
        const double delta     = delta_max * (1. - s * s);
        const double remaining = gauss_kronrod<double, 31>::integrate(
          force, delta, delta_max, 5, 1e-12);
        return 2. * delta_max * s / std::sqrt(2. * remaining / mass);
      };
      result.contact_time =
        2. * gauss_kronrod<double, 61>::integrate(integrand, 0., 1., 6, 1e-10);
      return result;
    }
  } // namespace Reference
} // namespace DiskImpact
