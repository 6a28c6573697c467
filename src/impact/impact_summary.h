#pragma once

#include <cmath>
#include <string>

namespace DiskImpact
{
  class CsvTable;

  /**
   * What an impact on the whole disk gives beyond the normal restitution
   * (velocities in units of c, spins of c / R, angles in degrees; NaN where
   * they do not apply). The wall's tangent t = e_z x n; the contact point
   * is the rim's point nearest the wall, with tangential velocity
   * v_t - omega R.
   */
  struct ObliqueSummary
  {
    double v_tangential_initial = std::nan(""); ///< centre of mass, along t
    double v_tangential_final   = std::nan("");
    double spin_initial         = std::nan(""); ///< omega about e_z
    double spin_final           = std::nan("");
    double v_contact_initial    = std::nan(""); ///< contact point, along t
    double v_contact_final      = std::nan("");
    /// The centre of mass's velocity after the impact against the normal.
    double rebound_angle = std::nan("");
    /// 2 v_contact / (mu (1 + epsilon) v_n,i) before and after.
    double psi_incident = std::nan("");
    double psi_rebound  = std::nan("");
    /// The largest angle [rad] the body turned while in contact: the
    /// kinematics are linear in it (docs/theory/friction.md).
    double rotation_in_contact = 0.;
    /// The energy friction dissipated / E(0).
    double friction_work = std::nan("");
    /// |m dv_t - J_t| / (m v_n,i) and |I d omega - J_theta| / (m v_n,i R).
    double tangential_impulse_error = std::nan("");
    double angular_impulse_error    = std::nan("");

    /// v_t,final / v_t,initial (NaN without a tangential velocity, below
    /// 1e-12 c).
    double
    tangential_restitution() const
    {
      return std::abs(v_tangential_initial) > 1e-12 ?
               v_tangential_final / v_tangential_initial :
               std::nan("");
    }
    /// -v_contact,final / v_contact,initial (-1: unchanged, 1: reversed;
    /// NaN as above).
    double
    contact_point_restitution() const
    {
      return std::abs(v_contact_initial) > 1e-12 ?
               -v_contact_final / v_contact_initial :
               std::nan("");
    }
  };

  /// What one impact gives (lengths in units of R, velocities of c).
  struct ImpactSummary
  {
    double       velocity          = 0.; ///< v_i / c
    double       epsilon           = 0.; ///< -v_com,final / v_com,initial
    double       contact_time      = 0.; ///< [R / c]
    double       delta_max         = 0.; ///< largest centre-of-mass approach
    double       force_max         = 0.; ///< largest force / (E2 R)
    /// The contact's largest half-width and the half-width the mesh is
    /// graded for ('Graded half-width', Hertz's or measured), over R.
    double contact_half_width_max = 0.;
    double graded_half_width      = 0.;
    /// The largest von Mises stress near the contact at the largest force
    /// (over E2; 2D models) and its depth below the contact point [R]:
    /// the body first yields where it reaches Y.
    double       von_mises_max = 0., von_mises_depth = 0.;
    /// An elastic-plastic body (NaN for an elastic one): the plastic work
    /// / E(0), the largest equivalent plastic strain and the plastic
    /// iterations of all steps.
    double       plastic_work          = std::nan("");
    double       plastic_strain_max    = std::nan("");
    unsigned int plastic_iterations    = 0;
    /// Factorizations of the plastic tangent ('Plastic solver' = Newton).
    unsigned int tangent_factorizations = 0;
    double       energy_error      = 0.; ///< max |E(t) - E(0)| / E(0)
    double       impulse_error     = 0.; ///< |m dv - sum F dt| / (m v_i)
    unsigned int steps             = 0;
    unsigned int newton_iterations = 0;
    unsigned int factorizations    = 0;
    unsigned int triangular_solves = 0;
    unsigned int n_dofs            = 0;
    double       time_step         = 0.;     ///< [R / c]
    double       wall_time_loop    = 0.;     ///< time stepping only [s]
    double       triangular_solve_time = 0.; ///< mean time of one solve [s]
    unsigned int contact_dofs  = 0; ///< DoFs the contact was condensed on
    unsigned int massless_dofs = 0; ///< DoFs without inertia
    /// Impact::dissipation_parameter(): Schwager's alpha of a disk, NaN
    /// for a sphere; Ramírez et al.'s u of a sphere, NaN for a disk.
    double schwager_alpha            = std::nan("");
    double ramirez_u                 = std::nan("");
    double one_dof_contact_time      = 0.; ///< 1-DOF log law [R / c]
    double one_dof_delta_max         = 0.; ///< 1-DOF log law, / R
    double one_dof_epsilon           = 1.; ///< 1-DOF law with viscosity
    double one_dof_epsilon_overlap   = 1.; ///< the same, ended at zero overlap
    double one_dof_epsilon_unloading = 1.; ///< Kelvin-Voigt unloading law
    /// The energy left in the body's vibration / E(0); with a partner
    /// also the partner's, and |m1 v1 + m2 v2| / (m* v_i) at the end (NaN
    /// for a wall), m* = m1 m2 / (m1 + m2).
    double vibration_fraction         = std::nan("");
    double partner_vibration_fraction = std::nan("");
    double momentum_error             = std::nan("");
    /// The largest resident memory of the run's processes, summed over
    /// the ranks [MB].
    double peak_memory_mb = 0.;
    /// The impact's angle of incidence [degrees] and the wall's friction
    /// coefficient.
    double         angle    = 0.;
    double         friction = 0.;
    ObliqueSummary oblique;
  };

  /// The one-row summary table of @p summary (summary.csv).
  CsvTable
  summary_table(const ImpactSummary &summary);
  /// summary.csv with one row.
  void
  write_summary(const ImpactSummary &summary, const std::string &filename);
} // namespace DiskImpact
