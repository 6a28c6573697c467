#include "reference/dem_contact_models.h"

#include "reference/hertz_impact.h"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

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

    namespace
    {
      /// epsilon and w_d t_c of the force-clipped linear spring-dashpot with
      /// damping ratio zeta (see yade_viscel_collision()).
      std::pair<double, double>
      clipped_linear_collision(const double zeta)
      {
        const double root_1 = std::sqrt(1. - zeta * zeta);
        const double b      = zeta / root_1;
        const double phase =
          M_PI - std::atan2(2. * zeta * root_1, 1. - 2. * zeta * zeta);
        const double speed_ratio = b * std::sin(phase) - std::cos(phase);
        return {std::exp(-b * phase) * speed_ratio,
                phase + std::sin(phase) / speed_ratio};
      }
    } // namespace

    LinearDashpotCollision
    yade_viscel_collision(const double en, const double tc)
    {
      const double log_en = std::log(en);
      const double zeta   = -log_en / std::sqrt(M_PI * M_PI + log_en * log_en);
      const auto [epsilon, phase_time] = clipped_linear_collision(zeta);
      return {epsilon, phase_time * tc / M_PI};
    }

    LinearDashpotCollision
    yade_viscel_inputs(const double epsilon, const double contact_time)
    {
      if (!(epsilon > 0. && epsilon <= 1.))
        throw std::domain_error("yade_viscel_inputs: epsilon outside (0, 1]");
      if (epsilon >= 1. - 1e-14)
        return {1., contact_time};
      // epsilon falls monotonically with zeta, from 1 at zeta = 0 to 0
      // at zeta = 1/sqrt(2) (th = pi/2, the force vanishes at once).
      boost::uintmax_t iterations = 200;
      const auto       root       = boost::math::tools::toms748_solve(
        [&](const double zeta) {
          return clipped_linear_collision(zeta).first - epsilon;
        },
        0.,
        M_SQRT1_2,
        boost::math::tools::eps_tolerance<double>(50),
        iterations);
      const double zeta = 0.5 * (root.first + root.second);
      const double damped_frequency =
        clipped_linear_collision(zeta).second / contact_time;
      return {std::exp(-M_PI * zeta / std::sqrt(1. - zeta * zeta)),
              M_PI / damped_frequency};
    }

    double
    lammps_viscoelastic_damping(const double dissipative_constant,
                                const double effective_modulus,
                                const double effective_mass)
    {
      return 2. * dissipative_constant * effective_modulus / effective_mass;
    }

    LinearSpringDashpot
    linear_spring_dashpot(const double epsilon,
                          const double contact_time,
                          const double effective_mass)
    {
      if (!(epsilon > 0. && epsilon <= 1.) || !(contact_time > 0.) ||
          !(effective_mass > 0.))
        throw std::domain_error("linear_spring_dashpot: needs 0 < epsilon <= "
                                "1, contact time > 0 and mass > 0");
      const double log_e = std::log(epsilon);
      return {effective_mass * (M_PI * M_PI + log_e * log_e) /
                (contact_time * contact_time),
              -2. * effective_mass * log_e / contact_time};
    }

    double
    thornton_ning_epsilon(const double u)
    {
      if (!(u > 0.))
        throw std::domain_error("thornton_ning_epsilon: needs v / v_y > 0");
      if (u <= 1.)
        return 1.;
      const double loading_work = 0.4 * u * u;
      const double x_m     = 1. + (std::sqrt(1.2 * u * u - 0.2) - 1.) / 1.5;
      const double f_m     = 1. + 1.5 * (x_m - 1.);
      const double hertz_m = x_m * std::sqrt(x_m); // x_m^{3/2}
      const double x_p     = std::pow(std::max(hertz_m - f_m, 0.), 2. / 3.);
      const double returned =
        (f_m - hertz_m) * (x_m - x_p) +
        0.4 * (x_m * x_m * std::sqrt(x_m) - x_p * x_p * std::sqrt(x_p));
      return std::sqrt(returned / loading_work);
    }

    double
    luding_epsilon(const double x, const double a)
    {
      if (!(x > 0.) || !(a > 0.))
        throw std::domain_error(
          "luding_epsilon: needs v / v_p > 0 and kp / k1 > 1");
      return x <= 1. ? 1. / std::sqrt(1. + a * x) :
                       std::sqrt(1. - a / ((1. + a) * x * x));
    }

    double
    luding_contact_time(const double x, const double a)
    {
      if (!(x > 0.) || !(a > 0.))
        throw std::domain_error(
          "luding_contact_time: needs v / v_p > 0 and kp / k1 > 1");
      if (x <= 1.)
        return 0.5 * M_PI * (1. + 1. / std::sqrt(1. + a * x));
      const double omega = std::sqrt(1. + a); // the kp branch's frequency
      const double s0    = 1. / (1. + a);     // d_p - d_p0, units of d_p
      return std::asin(1. / x) +
             (M_PI - std::atan2(s0 * omega, std::sqrt(x * x - 1.))) / omega;
    }
  } // namespace Reference
} // namespace DiskImpact
