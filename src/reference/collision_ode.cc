#include "reference/collision_ode.h"

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    Collision
    collide(const double       mass,
            const double       velocity,
            const ForceLaw    &law,
            const double       dissipation,
            const EndCriterion end,
            const double       tolerance)
    {
      using State      = std::array<double, 2>; // xi, xi'
      auto total_force = [&](const State &x) {
        return law.force(x[0]) + dissipation * x[1] * law.derivative(x[0]);
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
      stepper.initialize(State{0., velocity}, 0., 1e-8);
      Collision collision;
      for (unsigned int steps = 0; steps < 1000000; ++steps)
        {
          stepper.do_step(rhs);
          const State &x        = stepper.current_state();
          collision.max_overlap = std::max(collision.max_overlap, x[0]);
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
