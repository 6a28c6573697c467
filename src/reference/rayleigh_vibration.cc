#include "reference/rayleigh_vibration.h"

#include "reference/collision_ode.h"
#include "reference/log_contact_law.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    double
    RayleighVibration::epsilon() const
    {
      return std::sqrt(1. - vibration_fraction);
    }

    namespace
    {
      using State = std::array<double, 2>; // delta, delta'

      /// Gauss-Legendre rule on [a, b] applied to @p add(t, weight).
      template <typename Add>
      void
      gauss_panel(const double a, const double b, const Add &add)
      {
        using rule             = boost::math::quadrature::gauss<double, 8>;
        const double half      = 0.5 * (b - a);
        const double mid       = 0.5 * (a + b);
        const auto  &abscissae = rule::abscissa();
        const auto  &weights   = rule::weights();
        for (unsigned int i = 0; i < abscissae.size(); ++i)
          {
            add(mid - half * abscissae[i], half * weights[i]);
            add(mid + half * abscissae[i], half * weights[i]);
          }
      }

      /**
       * int_0^h P(t) cos(omega (h - t)) dt for every omega, P(t) the force
       * of the 1-DOF collision m delta'' = -P(delta) from delta' = @p
       * velocity up to its turning time h: Gauss panels no wider than
       * 1 / max omega on the Dormand-Prince dense output.
       */
      std::vector<double>
      half_pulse_projections(const ForceLaw            &law,
                             const double               mass,
                             const double               velocity,
                             const double               turning_time,
                             const std::vector<double> &omega)
      {
        const double omega_max = *std::max_element(omega.begin(), omega.end());
        std::vector<double> cosine_part(omega.size()), sine_part(omega.size());
        auto add_node = [&](auto &stepper, const double t, const double w) {
          State y;
          stepper.calc_state(t, y);
          const double force = law.force(y[0]);
          for (unsigned int k = 0; k < omega.size(); ++k)
            {
              cosine_part[k] += w * force * std::cos(omega[k] * t);
              sine_part[k] += w * force * std::sin(omega[k] * t);
            }
        };
        auto rhs = [&](const State &x, State &dxdt, double) {
          dxdt[0] = x[1];
          dxdt[1] = -law.force(x[0]) / mass;
        };
        auto stepper = boost::numeric::odeint::make_dense_output(
          1e-13, 1e-13, boost::numeric::odeint::runge_kutta_dopri5<State>());
        stepper.initialize(State{{0., velocity}}, 0., 1e-8);
        while (stepper.current_time() < turning_time)
          {
            stepper.do_step(rhs);
            const double a = stepper.previous_time();
            const double b = std::min(stepper.current_time(), turning_time);
            const auto   panels =
              static_cast<unsigned int>(std::ceil((b - a) * omega_max)) + 1;
            for (unsigned int p = 0; p < panels; ++p)
              gauss_panel(a + (b - a) * p / panels,
                          a + (b - a) * (p + 1) / panels,
                          [&](const double t, const double w) {
                            add_node(stepper, t, w);
                          });
          }
        std::vector<double> projection(omega.size());
        for (unsigned int k = 0; k < omega.size(); ++k)
          projection[k] = std::cos(omega[k] * turning_time) * cosine_part[k] +
                          std::sin(omega[k] * turning_time) * sine_part[k];
        return projection;
      }
    } // namespace

    RayleighVibration
    rayleigh_vibration(const double                          velocity,
                       const double                          constant,
                       const double                          nu2,
                       const std::vector<FreeDiskModeShape> &shapes)
    {
      const double   mass = M_PI;
      const ForceLaw law  = disk_force_law(1., 1., constant);
      // The elastic collision is time-reversible: force end = overlap end,
      // and the turning point is at half the contact time.
      const Collision collision =
        collide(mass, velocity, law, 0., EndCriterion::force);
      const double turning_time = 0.5 * collision.contact_time;

      RayleighVibration result;
      result.contact_time     = collision.contact_time;
      result.max_compression  = collision.max_overlap;
      const double        c_L = 1. / std::sqrt(1. - nu2 * nu2);
      std::vector<double> omega;
      for (const auto &shape : shapes)
        omega.push_back(shape.kappa() * c_L);

      const std::vector<double> projection =
        half_pulse_projections(law, mass, velocity, turning_time, omega);

      const double initial_energy = 0.5 * mass * velocity * velocity;
      for (unsigned int k = 0; k < shapes.size(); ++k)
        {
          const double C = shapes[k].edge_radial_amplitude();
          const double energy =
            2. * C * C / mass * projection[k] * projection[k];
          result.modes.push_back(
            {shapes[k].label(), omega[k], energy / initial_energy});
          result.vibration_fraction += energy / initial_energy;
        }
      return result;
    }

    namespace
    {
      /// State of the coupled model: delta, delta', then the N modal
      /// coordinates Q, then their rates (a flat vector for Boost.Odeint).
      using CoupledState = std::vector<double>;

      /// The contact force of the coupled model: P solves g(P) = delta +
      /// sum C Q with g(P) = D(P) - P S_N, the compliance of the contact
      /// zone and of the modes left out (D the log law of the centre's
      /// approach, S_N the N modes' quasistatic compliance).
      class FeedbackContact
      {
      public:
        FeedbackContact(const double               constant,
                        const std::vector<double> &edge_amplitudes,
                        const std::vector<double> &omega)
            : law(constant)
            , C(edge_amplitudes)
        {
          for (unsigned int k = 0; k < C.size(); ++k)
            compliance += C[k] * C[k] / (M_PI * omega[k] * omega[k]);
          // g is increasing up to g'(P) = 0, P = 4 pi e^{C - 1 - pi S_N}
          // (D' = (ln(4/x) + C - 1) / pi falls with P).
          largest_load = (1. - 1e-9) * 4. * M_PI *
                         std::exp(constant - 1. - M_PI * compliance);
        }

        /// The local compression delta + sum C Q.
        double
        compression(const CoupledState &state) const
        {
          double y = state[0];
          for (unsigned int k = 0; k < C.size(); ++k)
            y += C[k] * state[2 + k];
          return y;
        }

        /// P with D(P) - P S_N = y (zero for y <= 0).
        double
        force(const double y) const
        {
          if (!(y > 0.))
            return 0.;
          const double upper = largest_load;
          if (!(residual(upper, y) >= 0.))
            throw TooManyModes(
              "rayleigh_impact: the compression exceeds the range where the "
              "log law is stiffer than the modes (too many modes for this "
              "contact width)");
          boost::uintmax_t iterations = 200;
          const auto       root       = boost::math::tools::toms748_solve(
            [&](const double P) { return residual(P, y); },
            0.,
            upper,
            -y,
            residual(upper, y),
            boost::math::tools::eps_tolerance<double>(52),
            iterations);
          return 0.5 * (root.first + root.second);
        }

        /// Energy stored in the compliance g: int_0^P p g'(p) dp.
        double
        energy(const double P) const
        {
          if (!(P > 0.))
            return 0.;
          using boost::math::quadrature::gauss;
          return gauss<double, 30>::integrate(
            [&](const double p) { return p * slope(p); }, 0., P);
        }

      private:
        LogContactLaw       law;
        std::vector<double> C;
        double              compliance   = 0.;
        double              largest_load = 0.;

        double
        residual(const double P, const double y) const
        {
          return P > 0. ? law.compression(P / M_PI) - P * compliance - y : -y;
        }

        /// g'(P) = (ln(4/x) + C - 1) / pi - S_N.
        double
        slope(const double P) const
        {
          return (std::log(4. * M_PI / P) + law.constant() - 1.) / M_PI -
                 compliance;
        }
      };
    } // namespace

    RayleighImpact
    rayleigh_impact(const double                          velocity,
                    const double                          constant,
                    const double                          nu2,
                    const std::vector<FreeDiskModeShape> &shapes,
                    const double                          steps_per_period)
    {
      const double        mass = M_PI;
      const double        c_L  = 1. / std::sqrt(1. - nu2 * nu2);
      std::vector<double> omega, C;
      for (const auto &shape : shapes)
        {
          omega.push_back(shape.kappa() * c_L);
          C.push_back(shape.edge_radial_amplitude());
        }
      const FeedbackContact contact(constant, C, omega);
      const unsigned int    N = shapes.size();

      auto rhs = [&](const CoupledState &x, CoupledState &dxdt, double) {
        const double P = contact.force(contact.compression(x));
        dxdt[0]        = x[1];
        dxdt[1]        = -P / mass;
        for (unsigned int k = 0; k < N; ++k)
          {
            dxdt[2 + k]     = x[2 + N + k];
            dxdt[2 + N + k] = -omega[k] * omega[k] * x[2 + k] - C[k] * P / mass;
          }
      };
      auto vibration_energy = [&](const CoupledState &x) {
        double energy = 0.;
        for (unsigned int k = 0; k < N; ++k)
          energy += 0.5 * mass *
                    (x[2 + N + k] * x[2 + N + k] +
                     omega[k] * omega[k] * x[2 + k] * x[2 + k]);
        return energy;
      };

      const double estimate = collide(mass,
                                      velocity,
                                      disk_force_law(1., 1., constant),
                                      0.,
                                      EndCriterion::force)
                                .contact_time;
      const double omega_max = *std::max_element(omega.begin(), omega.end());
      // The force's own time scale bounds the step when the modes are few.
      const double dt =
        std::min(2. * M_PI / (steps_per_period * omega_max), estimate / 2000.);
      const double initial_energy = 0.5 * mass * velocity * velocity;

      CoupledState state(2 + 2 * N, 0.);
      state[1] = velocity;
      boost::numeric::odeint::runge_kutta4<CoupledState> stepper;
      RayleighImpact                                     result;
      double t = 0., end = 0., previous_y = 0.;
      bool   touched = false;
      while (!(end > 0.) || t < 1.2 * end)
        {
          stepper.do_step(rhs, state, t, dt);
          t += dt;
          result.max_compression = std::max(result.max_compression, state[0]);
          const double y         = contact.compression(state);
          if (y > 0.)
            touched = true;
          else if (touched && previous_y > 0.)
            end = t - dt * y / (y - previous_y); // linear zero crossing
          previous_y = y;
          if (t > 100. * estimate)
            throw std::runtime_error("rayleigh_impact: the collision did not "
                                     "end");
        }
      const double vibration = vibration_energy(state);
      const double total =
        0.5 * mass * state[1] * state[1] + vibration +
        contact.energy(contact.force(contact.compression(state)));
      result.contact_time = end;
      result.epsilon      = -state[1] / velocity;
      result.energy_error = std::abs(total - initial_energy) / initial_energy;
      result.vibration_fraction = vibration / initial_energy;
      return result;
    }
  } // namespace Reference
} // namespace DiskImpact
