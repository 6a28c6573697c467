#pragma once

#include "body/geometry.h"
#include "reference/collision_estimate.h"
#include "reference/two_body_contact.h"

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <mpi.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace DiskImpact
{
  class CsvTable;
  struct Parameters;
  struct ImpactOperators;

  /// What one impact gives (lengths in units of R, velocities of c).
  struct ImpactSummary
  {
    double       velocity          = 0.; ///< v_i / c
    double       epsilon           = 0.; ///< -v_com,final / v_com,initial
    double       contact_time      = 0.; ///< [R / c]
    double       delta_max         = 0.; ///< largest centre-of-mass approach
    double       force_max         = 0.; ///< largest force / (E2 R)
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
  };

  /**
   * Task 'impact': the disk, undeformed, moving toward the wall with speed
   * v (subsection Impact), touching it at t = 0. Implicit time integration
   * (TimeIntegrator), one factorization of the effective matrix and the
   * contact condensed on its DoFs, solved by Newton's method
   * (CondensedSolver); runs until the contact force has
   * returned to zero (Schwager & Pöschel 2007) plus a margin. Writes
   * impact.csv, summary.csv and impact.pvd.
   */
  class Impact
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    velocity() const;
    void
    set_velocity(double v);
    /// The sweep's velocities, Poisson ratios, relaxation times and
    /// partner radii (the latter three empty: the material's, the
    /// partner's).
    const std::vector<double> &
    velocities() const;
    const std::vector<double> &
    poisson_ratios() const;
    const std::vector<double> &
    relaxation_times() const;
    const std::vector<double> &
    partner_radii() const;
    bool
    estimate_errors() const;
    /// Throws an InputError unless 0 < v <= @p largest for 'Velocity' and
    /// every entry of 'Velocities' (0.5 against the wall, 1 for the
    /// relative speed of two bodies).
    void
    check_velocities(double largest) const;
    /// Task 'sweep': whether to keep an earlier sweep's finished points.
    bool
    resume() const;
    /// The same impact on a mesh with every element size halved @p levels
    /// times near the contact: elements across it * 2^levels, grading /
    /// 2^levels (global refinements are the geometry's).
    Impact
    with_mesh_refined(unsigned int levels) const;

    /// The 1-DOF log-law collision at this velocity (beyond the log law's
    /// range: Gerl & Zippelius' eq. 61 for the contact time and load).
    CollisionEstimate
    estimate_collision(const Parameters &parameters) const;
    /// Throws an InputError unless a fixed 'Time step' suits the contact
    /// time estimate_collision() expects (TimeIntegrator::check_time_step()).
    void
    check_time_step(const Parameters &parameters) const;
    /// estimate_collision() of two bodies (subsection Partner).
    CollisionEstimate
    estimate_pair_collision(const Parameters &parameters) const;
    /// The Hertz half-width at the largest expected force [length]: the
    /// contact zone the mesh is graded for.
    double
    largest_half_width(const Parameters &parameters) const;
    /// The half-width the mesh is graded for [length]: 'Graded half-width'
    /// if set, else largest_half_width().
    double
    graded_width(const Parameters &parameters) const;
    /// The impact's mesh: the geometry's, graded toward the contact point;
    /// throws an InputError if it would exceed about @p max_cells cells.
    void
    create_mesh(
      const Parameters         &parameters,
      dealii::Triangulation<2> &triangulation,
      double max_cells = std::numeric_limits<double>::infinity()) const;

    /// The modulus of the contact: the body's E2 against the wall; against
    /// a deformable partner the pair's, 1 / (1 / E2 + 1 / E2').
    static double
    contact_modulus(const Parameters &parameters);

    /// The constant of the 1-DOF model's wall law: a disk's C, a sphere's D.
    double
    contact_law_constant_value(const Parameters &parameters) const;

    /// The contact radius of Hertz's largest approach at the impact speed:
    /// the sphere on the wall, or the pair (subsection Partner).
    double
    hertz_contact_radius(const Parameters &parameters) const;

    /// A sphere's derived finite-size constant D = D0 + D1 ln(a/R) at
    /// contact radius @p contact_radius; @p body gives R and nu.
    double
    finite_size_constant(const Parameters &body, double contact_radius) const;

    /// The body and its partner (subsection Partner) as the two-body law
    /// sees them: radius, modulus (E2 of a disk, E* of a sphere) and the
    /// constant of each one's wall law (contact_law_constant_value()).
    std::pair<Reference::ContactBody, Reference::ContactBody>
    contact_bodies(const Parameters &parameters) const;

    /**
     * The body's dimensionless dissipation: for a disk Schwager's
     * alpha = tau sqrt(pi E2 / m) (Schwager 2007), for a sphere Ramírez et
     * al.'s u = (v / g*)^{1/5} (eq. 32), both with A = tau; 0 if elastic.
     */
    double
    dissipation_parameter(const Parameters &parameters) const;

    /// The unit of the reported forces: E2 R for a disk (per unit
    /// thickness), E2 R^2 = E* R^2 for a sphere.
    static double
    force_unit(const Parameters &parameters);

    /// The units of the outputs, in words (HDF5 attribute, messages).
    static std::string
    units(const Parameters &parameters);

    /// One impact; with @p operators, on those (built for @p parameters
    /// but perhaps another time step) instead of its own.
    ImpactSummary
    run(const Parameters                &parameters,
        MPI_Comm                         communicator,
        bool                             write_time_series = true,
        std::shared_ptr<ImpactOperators> operators         = {}) const;

    /// summary.csv with one row.
    static void
    write_summary(const ImpactSummary &summary, const std::string &filename);
    /// The one-row summary table.
    static CsvTable
    summary_table(const ImpactSummary &summary);

    /// The angle of the sphere's 3D view in degrees (0: none).
    double
    revolved_view() const
    {
      return revolved_view_angle;
    }
    /// Steps between ParaView snapshots (0: none).
    unsigned int
    snapshot_interval() const
    {
      return output_interval;
    }
    /// 'Time after contact': the run goes on for this fraction of the
    /// contact time after the contact has ended.
    double
    time_after_contact() const
    {
      return margin;
    }
    /// 'Number of projected modes' (0: no mode energies).
    unsigned int
    n_projected_modes() const
    {
      return projected_modes;
    }

  private:
    double              impact_velocity = 0.01;
    std::vector<double> sweep_velocities;
    std::vector<double> sweep_poisson_ratios;
    std::vector<double> sweep_relaxation_times;
    std::vector<double> sweep_partner_radii;
    bool                error_estimate          = true;
    bool                resume_sweep            = true;
    unsigned int        elements_across_contact = 12;
    double              grading                 = 0.3;
    double              fine_zone_radius        = default_fine_zone_radius;
    double              graded_half_width       = 0.;
    std::string         contact_law_constant    = "exact";
    double              margin                  = 0.2;
    unsigned int        output_interval         = 20;
    double              revolved_view_angle     = 0.; ///< degrees; 0: none
    unsigned int        projected_modes         = 20;
  };
} // namespace DiskImpact
