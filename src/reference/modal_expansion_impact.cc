#include "reference/modal_expansion_impact.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    namespace
    {
      /// Points with alpha xi below this add less than e^-50 to the sums.
      constexpr double negligible_exponent = -50.;

      /// Length of the flight from the gap back to the gap, in units of
      /// (R + gap) / v, after which a collision counts as a capture.
      constexpr double max_flight_lengths = 10.;
    } // namespace

    ModalExpansionImpact::ModalExpansionImpact(const ModalImpactConfig &cfg)
        : ModalExpansionImpact(cfg,
                               symmetric_mode_shapes(cfg.in_plane_poisson_ratio,
                                                     cfg.n_modes))
    {
    }

    ModalExpansionImpact::ModalExpansionImpact(
      const ModalImpactConfig              &cfg,
      const std::vector<FreeDiskModeShape> &basis)
        : config(cfg)
        , mass(M_PI)
        , gap(cfg.initial_gap > 0. ? cfg.initial_gap : 30. / cfg.alpha)
    {
      if (!(config.velocity > 0.) || !(config.alpha > 0.) ||
          config.angular_points < 2 || !(config.steps_per_period > 2.))
        throw std::invalid_argument(
          "ModalExpansionImpact: need v > 0, alpha > 0, at least 2 angular "
          "points and more than 2 steps per period");

      if (basis.size() < config.n_modes)
        throw std::invalid_argument(
          "ModalExpansionImpact: the basis holds fewer modes than n_modes");
      const double nu2 = config.in_plane_poisson_ratio;
      const double c_L = 1. / std::sqrt(1. - nu2 * nu2);
      shapes.assign(basis.begin(), basis.begin() + config.n_modes);
      for (const auto &shape : shapes)
        {
          const ModeLabel &label = shape.label();
          omega.push_back(shape.kappa() * c_L);
          edge_C.push_back(shape.edge_radial_amplitude());
          edge_S.push_back(shape.edge_tangential_amplitude());
          order.push_back(label.n);
          n_orders = std::max(n_orders, label.n + 1);
        }

      // Trapezoidal rule on 0 <= phi <= pi/2, weights doubled for the
      // mirror half -pi/2 <= phi < 0.
      const unsigned int M = config.angular_points;
      const double       h = 0.5 * M_PI / (M - 1);
      for (unsigned int j = 0; j < M; ++j)
        {
          const double phi = j * h;
          phi_cos.push_back(std::cos(phi));
          phi_weight.push_back(j == 0 || j == M - 1 ? h : 2. * h);
          for (unsigned int n = 0; n < n_orders; ++n)
            {
              cos_table.push_back(std::cos(n * phi) * std::cos(phi));
              sin_table.push_back(std::sin(n * phi) * std::sin(phi));
            }
        }
    }

    const std::vector<FreeDiskModeShape> &
    ModalExpansionImpact::mode_shapes() const
    {
      return shapes;
    }

    double
    ModalExpansionImpact::time_step() const
    {
      const double fastest =
        std::max(omega.empty() ? 0. :
                                 *std::max_element(omega.begin(), omega.end()),
                 config.alpha * config.velocity);
      return 2. * M_PI / fastest / config.steps_per_period;
    }

    void
    ModalExpansionImpact::evaluate(const State &state, EdgeForces &forces) const
    {
      // Edge amplitudes per angular order: u_r(1, phi) = sum_n a_n cos n phi,
      // u_phi(1, phi) = sum_n b_n sin n phi (Gerl & Zippelius 1999, eq. 38).
      std::vector<double> a(n_orders, 0.), b(n_orders, 0.);
      for (unsigned int k = 0; k < omega.size(); ++k)
        {
          a[order[k]] += edge_C[k] * state.Q[k];
          b[order[k]] += edge_S[k] * state.Q[k];
        }

      // xi = x0 + cos phi + u_r cos phi - u_phi sin phi (eq. 40); the
      // weighted e^{alpha xi} of every point is accumulated into the sums
      // c_n = int e^{alpha xi} cos n phi cos phi, s_n likewise.
      std::vector<double> c(n_orders, 0.), s(n_orders, 0.);
      forces.wall_sum = 0.;
      forces.front    = -std::numeric_limits<double>::infinity();
      for (unsigned int j = 0; j < phi_cos.size(); ++j)
        {
          const double *ct = &cos_table[j * n_orders];
          const double *st = &sin_table[j * n_orders];
          double        xi = state.x0 + phi_cos[j];
          for (unsigned int n = 0; n < n_orders; ++n)
            xi += ct[n] * a[n] - st[n] * b[n];
          forces.front = std::max(forces.front, xi);
          if (config.alpha * xi < negligible_exponent)
            continue;
          const double e = phi_weight[j] * std::exp(config.alpha * xi);
          forces.wall_sum += e;
          for (unsigned int n = 0; n < n_orders; ++n)
            {
              c[n] += e * ct[n];
              s[n] += e * st[n];
            }
        }

      forces.modal.resize(omega.size());
      for (unsigned int k = 0; k < omega.size(); ++k)
        forces.modal[k] = edge_C[k] * c[order[k]] - edge_S[k] * s[order[k]];
    }

    void
    ModalExpansionImpact::splitting_step(State       &state,
                                         EdgeForces  &forces,
                                         const double dt) const
    {
      auto half_kick = [&]() {
        state.v -= 0.5 * dt * forces.wall_sum / mass;
        for (unsigned int k = 0; k < omega.size(); ++k)
          state.V[k] -= 0.5 * dt * forces.modal[k] / mass;
      };

      half_kick();
      state.x0 += dt * state.v;
      for (unsigned int k = 0; k < omega.size(); ++k)
        {
          const double w = omega[k], cs = std::cos(w * dt),
                       sn = std::sin(w * dt);
          const double Q = state.Q[k], V = state.V[k];
          state.Q[k] = Q * cs + V / w * sn;
          state.V[k] = -w * Q * sn + V * cs;
        }
      evaluate(state, forces);
      half_kick();
    }

    void
    ModalExpansionImpact::runge_kutta_step(State       &state,
                                           EdgeForces  &forces,
                                           const double dt) const
    {
      // Interaction picture relative to the step start (the phase origin
      // does not change RK4): Q - i V / omega = q e^{i omega tau},
      // dq/dtau = (i / (m omega)) e^{-i omega tau} dU/dQ (eq. 44 corrected).
      using complex          = std::complex<double>;
      const unsigned int   N = omega.size();
      std::vector<complex> q0(N), q(N), phase_half(N), phase_full(N);
      for (unsigned int k = 0; k < N; ++k)
        {
          q0[k]         = complex(state.Q[k], -state.V[k] / omega[k]);
          phase_half[k] = std::polar(1., 0.5 * omega[k] * dt);
          phase_full[k] = phase_half[k] * phase_half[k];
        }

      struct Slope
      {
        double               x0, v;
        std::vector<complex> q;
      };
      auto slope = [&](const State                &at,
                       const EdgeForces           &f,
                       const std::vector<complex> *phase) {
        Slope d{at.v, -f.wall_sum / mass, std::vector<complex>(N)};
        for (unsigned int k = 0; k < N; ++k)
          {
            d.q[k] = complex(0., f.modal[k] / (mass * omega[k]));
            if (phase)
              d.q[k] *= std::conj((*phase)[k]);
          }
        return d;
      };
      auto stage = [&](const Slope                &d,
                       const double                tau,
                       const std::vector<complex> &phase) {
        State s;
        s.x0 = state.x0 + tau * d.x0;
        s.v  = state.v + tau * d.v;
        s.Q.resize(N);
        s.V.resize(N);
        for (unsigned int k = 0; k < N; ++k)
          {
            const complex z = (q0[k] + tau * d.q[k]) * phase[k];
            s.Q[k]          = z.real();
            s.V[k]          = -omega[k] * z.imag();
          }
        return s;
      };

      const Slope k1 = slope(state, forces, nullptr);
      State       s  = stage(k1, 0.5 * dt, phase_half);
      evaluate(s, forces);
      const Slope k2 = slope(s, forces, &phase_half);
      s              = stage(k2, 0.5 * dt, phase_half);
      evaluate(s, forces);
      const Slope k3 = slope(s, forces, &phase_half);
      s              = stage(k3, dt, phase_full);
      evaluate(s, forces);
      const Slope k4 = slope(s, forces, &phase_full);

      Slope mean{(k1.x0 + 2. * k2.x0 + 2. * k3.x0 + k4.x0) / 6.,
                 (k1.v + 2. * k2.v + 2. * k3.v + k4.v) / 6.,
                 std::vector<complex>(N)};
      for (unsigned int k = 0; k < N; ++k)
        mean.q[k] = (k1.q[k] + 2. * k2.q[k] + 2. * k3.q[k] + k4.q[k]) / 6.;
      state = stage(mean, dt, phase_full);
      evaluate(state, forces);
    }

    double
    ModalExpansionImpact::modal_energy(const State       &state,
                                       const unsigned int k) const
    {
      const double Q = state.Q[k], V = state.V[k], w = omega[k];
      return 0.5 * mass * (V * V + w * w * Q * Q);
    }

    ModalImpactResult
    ModalExpansionImpact::run() const
    {
      const unsigned int N        = omega.size();
      const double       dt       = time_step();
      const double       v0       = config.velocity;
      const double       kinetic0 = 0.5 * mass * v0 * v0;
      const double       threshold =
        config.contact_threshold * config.alpha * kinetic0;

      State state;
      state.x0 = -1. - gap;
      state.v  = v0;
      state.Q.assign(N, 0.);
      state.V.assign(N, 0.);
      EdgeForces forces;
      evaluate(state, forces);

      auto hamiltonian = [&]() {
        double H =
          0.5 * mass * state.v * state.v + forces.wall_sum / config.alpha;
        for (unsigned int k = 0; k < N; ++k)
          H += modal_energy(state, k);
        return H;
      };

      ModalImpactResult result;
      result.time_step       = dt;
      const double        H0 = hamiltonian();
      std::vector<double> energy_in_contact(N, 0.);
      double       time_in_contact = 0., contact_start = -1., contact_end = -1.;
      double       t = 0., previous_force = forces.wall_sum;
      const double t_max = max_flight_lengths * (1. + gap) / v0;

      while (t < t_max)
        {
          if (config.integrator == ModalIntegrator::strang_splitting)
            splitting_step(state, forces, dt);
          else
            runge_kutta_step(state, forces, dt);
          t += dt;
          ++result.steps;

          const double force = forces.wall_sum;
          result.max_force   = std::max(result.max_force, force);
          result.energy_error =
            std::max(result.energy_error, std::abs(hamiltonian() - H0) / H0);

          // Threshold crossings, linearly interpolated within the step.
          if ((previous_force - threshold) * (force - threshold) < 0.)
            {
              const double crossing =
                t - dt * (force - threshold) / (force - previous_force);
              if (contact_start < 0.)
                contact_start = crossing;
              if (force < threshold)
                contact_end = crossing;
            }
          if (force > threshold)
            {
              time_in_contact += dt;
              for (unsigned int k = 0; k < N; ++k)
                energy_in_contact[k] += dt * modal_energy(state, k);
            }
          previous_force = force;

          if (state.v < 0. && forces.front < -gap)
            {
              result.separated = true;
              break;
            }
        }

      // A stiff wall and a fast impact can keep the elastic disk's force
      // below the threshold, a fraction of the rigid disk's peak: then the
      // run has no contact window, and neither a contact time nor averages.
      const double not_measured = std::numeric_limits<double>::quiet_NaN();
      const bool   window       = contact_start >= 0. && contact_end >= 0.;
      result.epsilon            = -state.v / v0;
      result.contact_time = window ? contact_end - contact_start : not_measured;
      for (unsigned int k = 0; k < N; ++k)
        result.modes.push_back(
          {shapes[k].label(),
           omega[k],
           modal_energy(state, k) / kinetic0,
           window ? energy_in_contact[k] / time_in_contact / kinetic0 :
                    not_measured});
      return result;
    }
  } // namespace Reference
} // namespace DiskImpact
