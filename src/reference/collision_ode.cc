#include "reference/collision_ode.h"

#include "reference/log_contact_law.h"

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    ForceLaw
    disk_force_law(const double in_plane_young_modulus,
                   const double radius,
                   const double constant)
    {
      const LogContactLaw law(constant);
      const double        scale = M_PI * in_plane_young_modulus;
      return {[=](const double xi) {
                return xi > 0. ? scale * radius * law.load(xi / radius) : 0.;
              },
              [=](const double xi) {
                if (!(xi > 0.))
                  return 0.;
                const double x = law.load(xi / radius);
                return scale / (std::log(4. / x) + constant - 1.);
              }};
    }

    namespace
    {
      /// The overlap where the velocity, positive at the start of the
      /// stepper's last step and not at its end, vanishes (bisection in the
      /// dense output).
      template <typename Stepper>
      double
      turning_point(Stepper &stepper)
      {
        std::array<double, 2> y;
        double a = stepper.previous_time(), b = stepper.current_time();
        for (unsigned int it = 0; it < 200 && b - a > 1e-16 * b; ++it)
          {
            const double m = 0.5 * (a + b);
            stepper.calc_state(m, y);
            (y[1] > 0. ? a : b) = m;
          }
        stepper.calc_state(b, y);
        return y[0];
      }
    } // namespace

    Collision
    collide(const double       mass,
            const double       velocity,
            const ForceLaw    &law,
            const double       dissipation,
            const EndCriterion end,
            const double       tolerance)
    {
      return collide(
        mass,
        velocity,
        law,
        [&](const double xi, const double xi_dot) {
          return dissipation * xi_dot * law.derivative(xi);
        },
        end,
        tolerance);
    }

    std::function<double(double, double)>
    kelvin_voigt_unloading_force(const ForceLaw &law,
                                 const double    relaxation_time)
    {
      return [law, relaxation_time](const double xi, const double xi_dot) {
        if (xi_dot >= 0.)
          return relaxation_time * xi_dot * law.derivative(xi);
        return law.force(xi + relaxation_time * xi_dot) - law.force(xi);
      };
    }

    Collision
    collide(const double                                 mass,
            const double                                 velocity,
            const ForceLaw                              &law,
            const std::function<double(double, double)> &dissipative_force,
            const EndCriterion                           end,
            const double                                 tolerance)
    {
      using State      = std::array<double, 2>; // xi, xi'
      auto total_force = [&](const State &x) {
        return law.force(x[0]) + dissipative_force(x[0], x[1]);
      };
      auto rhs = [&](const State &x, State &dxdt, double) {
        dxdt[0] = x[1];
        dxdt[1] = -total_force(x) / mass;
      };
      // The collision is over where this changes sign from + to -.
      auto indicator = [&](const State &x) {
        return end == EndCriterion::force ? total_force(x) : x[0];
      };

      auto stepper = boost::numeric::odeint::make_dense_output(
        tolerance,
        tolerance,
        boost::numeric::odeint::runge_kutta_dopri5<State>());
      // The adaptive stepper grows the first step to what the law needs.
      stepper.initialize(State{{0., velocity}}, 0., 1e-8);
      Collision collision;
      for (unsigned int steps = 0; steps < 1000000; ++steps)
        {
          stepper.do_step(rhs);
          const State &x = stepper.current_state();
          if (x[1] <= 0. && collision.max_overlap == 0.)
            collision.max_overlap = turning_point(stepper);
          if (!(indicator(x) <= 0.) || x[1] > 0.)
            continue;
          // Bisect for the sign change in the last step's dense output.
          double a = stepper.previous_time(), b = stepper.current_time();
          State  y;
          for (unsigned int it = 0; it < 200 && b - a > 1e-16 * b; ++it)
            {
              const double m = 0.5 * (a + b);
              stepper.calc_state(m, y);
              (indicator(y) > 0. ? a : b) = m;
            }
          stepper.calc_state(b, y);
          collision.contact_time = b;
          collision.epsilon      = -y[1] / velocity;
          return collision;
        }
      throw std::runtime_error("collide: the collision did not end");
    }
  } // namespace Reference
} // namespace DiskImpact
