#include "reference/dem_contact_models.h"

#include "reference/hertz_impact.h"

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    double
    liggghts_hertz_epsilon(const double coefficient_restitution)
    {
      if (coefficient_restitution >= 1.)
        return 1.;
      // Scale-free: m = E* = R = v = 1 (wall: Y* = E*, R* = R, m* = m).
      const double   log_e = std::log(coefficient_restitution);
      const double   beta  = log_e / std::sqrt(log_e * log_e + M_PI * M_PI);
      const ForceLaw hertz{
        [](const double d) { return d > 0. ? 4. / 3. * d * std::sqrt(d) : 0.; },
        [](const double d) { return d > 0. ? 2. * std::sqrt(d) : 0.; }};
      const auto damping = [&](const double d, const double d_dot) {
        const double s_n = d > 0. ? 2. * std::sqrt(d) : 0.;
        return 2. * std::sqrt(5. / 6.) * std::abs(beta) * std::sqrt(s_n) *
               d_dot;
      };
      return collide(1., 1., hertz, damping, EndCriterion::overlap).epsilon;
    }

    double
    liggghts_hertz_input(const double epsilon)
    {
      if (!(epsilon > 0. && epsilon <= 1.))
        throw std::domain_error("liggghts_hertz_input: epsilon outside (0, 1]");
      if (epsilon >= 1. - 1e-14)
        return 1.;
      boost::uintmax_t iterations = 100;
      const auto       root       = boost::math::tools::toms748_solve(
        [&](const double e) { return liggghts_hertz_epsilon(e) - epsilon; },
        1e-6,
        1. - 1e-15,
        boost::math::tools::eps_tolerance<double>(45),
        iterations);
      return 0.5 * (root.first + root.second);
    }

    double
    lammps_viscoelastic_damping(const double dissipative_constant,
                                const double effective_modulus,
                                const double effective_mass)
    {
      return 2. * dissipative_constant * effective_modulus / effective_mass;
    }
  } // namespace Reference
} // namespace DiskImpact
