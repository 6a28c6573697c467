#pragma once

#include "reference/free_disk_mode_shapes.h"
#include "reference/free_disk_modes.h"

#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /// Time integrators of the modal equations of motion.
    enum class ModalIntegrator
    {
      /// Half kick by the wall force, exact rotation of every oscillator and
      /// free drift of x0, half kick: symplectic, second order.
      strang_splitting,
      /// Classical RK4 on the interaction-picture amplitudes q (Gerl &
      /// Zippelius 1999, eq. 44 corrected) and (x0, v), as in the paper.
      runge_kutta_interaction_picture
    };

    /**
     * Set-up of a modal-expansion collision. Units: R = rho = E2 = 1, so
     * lengths are in R, velocities in c = sqrt(E2 / rho), times in R / c,
     * forces per unit thickness in E2 R and the mass is m = pi.
     */
    struct ModalImpactConfig
    {
      double in_plane_poisson_ratio = 0.33; ///< nu2
      double velocity               = 0.1;  ///< v / c before the impact
      double alpha                  = 100.; ///< stiffness of the wall
      /// The lowest modes of the set symmetric about the impact axis.
      unsigned int n_modes = 100;
      /// Trapezoidal points on the quarter circle 0 <= phi <= pi/2 (the
      /// half circle facing the wall by symmetry).
      unsigned int angular_points = 256;
      /// Time steps per 2 pi / max(omega_max, alpha v / R).
      double steps_per_period = 20.;
      /// Initial distance between the edge and the wall; <= 0: 30 R / alpha,
      /// where the wall potential is e^-30 of its value at contact.
      double initial_gap = 0.;
      /// Contact: wall force above this fraction of the rigid-disk peak
      /// force alpha m v^2 / (2 R).
      double contact_threshold = 0.01;
      /// The more accurate per force evaluation on one collision (measured
      /// in docs/theory/modal-expansion-model.md).
      ModalIntegrator integrator =
        ModalIntegrator::runge_kutta_interaction_picture;
    };

    /// One mode's share of the collision (energies / (m v^2 / 2)).
    struct ModeEnergy
    {
      ModeLabel label;
      double    omega        = 0.;
      double    energy_after = 0.; ///< after the collision
      /// Time average over the contact; NaN without a contact window.
      double average_energy = 0.;
    };

    /// Outcome of a modal-expansion collision.
    struct ModalImpactResult
    {
      double epsilon = 0.; ///< -v_com after / v before
      /// Time with the force above the threshold; NaN if it never was.
      double       contact_time = 0.;
      double       max_force    = 0.; ///< largest wall force on the disk
      double       energy_error = 0.; ///< max |H(t) - H(0)| / H(0)
      double       time_step    = 0.;
      unsigned int steps        = 0;
      bool         separated = false; ///< edge back at the initial gap, v < 0
      std::vector<ModeEnergy> modes;
    };

    /**
     * Collision of an elastic disk with a rigid wall in the modal expansion
     * of Gerl & Zippelius 1999, sections 3-4: rigid translation x0 plus the
     * free-disk modes as independent oscillators (modal mass m, eqs. 26, 32,
     * 34), pushed along the edge by the wall potential U = int w(xi(phi)) R d
     * phi,  w(xi) = (E2 / alpha) e^{alpha xi / R}, xi the x-coordinate of the
     * deformed edge (eq. 40), the wall at x = 0. Equations of motion (eqs. 41,
     * 42, 45 corrected): m x0'' = -int e^{alpha xi} d phi, m (Q_k'' + omega_k^2
     * Q_k) = -int e^{alpha xi} (C_k cos n phi cos phi - S_k sin n phi sin phi)
     *       d phi.
     * The edge displacement is a sum over angular orders n: per step the
     * modal amplitudes are gathered per order and the edge sums are products
     * with a table of cos n phi cos phi, sin n phi sin phi.
     */
    class ModalExpansionImpact
    {
    public:
      /// Finds the modes and their shapes.
      explicit ModalExpansionImpact(const ModalImpactConfig &config);

      /// With the first config.n_modes of the given shapes
      /// (symmetric_mode_shapes() for the same Poisson ratio).
      ModalExpansionImpact(const ModalImpactConfig              &config,
                           const std::vector<FreeDiskModeShape> &basis);

      /// Integrates one collision from the initial gap until separation.
      ModalImpactResult
      run() const;

      const std::vector<FreeDiskModeShape> &
      mode_shapes() const;

      /// Time step from ModalImpactConfig::steps_per_period.
      double
      time_step() const;

    private:
      /// Wall force and generalized forces at one state.
      struct EdgeForces
      {
        double              wall_sum = 0.; ///< int e^{alpha xi} d phi
        double              front    = 0.; ///< max_phi xi
        std::vector<double> modal;         ///< dU / dQ_k
      };

      /// Positions x0, Q_k and velocities v, V_k = P_k / m.
      struct State
      {
        double              x0 = 0., v = 0.;
        std::vector<double> Q, V;
      };

      ModalImpactConfig              config;
      double                         mass;
      double                         gap;
      std::vector<FreeDiskModeShape> shapes;
      std::vector<double>            omega;
      std::vector<double>            edge_C, edge_S;
      std::vector<unsigned int>      order;
      unsigned int                   n_orders = 0;
      std::vector<double>            phi_cos, phi_weight;
      /// cos(n phi_j) cos(phi_j) and sin(n phi_j) sin(phi_j), row j.
      std::vector<double> cos_table, sin_table;

      void
      evaluate(const State &state, EdgeForces &forces) const;

      /// One step of the symplectic splitting; @p forces in and out.
      void
      splitting_step(State &state, EdgeForces &forces, double dt) const;

      /// One RK4 step of the interaction picture; @p forces in and out.
      void
      runge_kutta_step(State &state, EdgeForces &forces, double dt) const;

      double
      modal_energy(const State &state, unsigned int k) const;
    };
  } // namespace Reference
} // namespace DiskImpact
