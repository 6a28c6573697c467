#pragma once

#include "body/geometry.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * Subsection Impact: the impact speed, the mesh graded toward the contact
   * point, the 1-DOF reference model's wall-law constant, the outputs of
   * one impact and the lists a sweep runs through. The physics that reads
   * them is in impact/ (ImpactSimulation, impact_estimates.h).
   */
  class ImpactParameters
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// 'Velocity': the impact speed v_i (units of c).
    double
    velocity() const;
    void
    set_velocity(double v);
    /// v_i cos(theta) toward the wall and v_i sin(theta) along its tangent
    /// (units of c), theta the 'Angle of incidence'.
    double
    normal_velocity() const;
    double
    tangential_velocity() const;
    /// 'Angle of incidence' [degrees].
    double
    incidence_angle_degrees() const
    {
      return incidence_angle;
    }
    void
    set_incidence_angle_degrees(const double angle)
    {
      incidence_angle = angle;
    }
    /// 'Spin': the angular velocity before the impact (units of c / R).
    double
    spin() const
    {
      return initial_spin;
    }
    /// Whether the impact is oblique (or a sweep's is) or the body spins.
    bool
    is_oblique() const;
    /// Task 'sweep': the 'Angles of incidence' (empty: 'Angle of
    /// incidence').
    const std::vector<double> &
    incidence_angles() const;
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
    ImpactParameters
    with_mesh_refined(unsigned int levels) const;
    /// The mesh one level coarser: half the elements across the contact,
    /// twice the grading ('Graded mesh = conforming' halves it again).
    ImpactParameters
    with_mesh_coarsened() const;
    /// The mesh graded for the half-width @p half_width (over R) with
    /// @p elements across it and @p grading, conforming if @p conforming
    /// (a mesh made for a load instead of an impact).
    ImpactParameters
    with_mesh_graded_for(double       half_width,
                         unsigned int elements,
                         double       grading,
                         bool         conforming) const;

    /// 'Elements across contact', 'Grading', 'Fine zone radius' and
    /// 'Graded half-width' (0: Hertz's half-width at the largest force).
    unsigned int
    elements_across_contact() const
    {
      return contact_elements;
    }
    double
    grading() const
    {
      return mesh_grading;
    }
    double
    fine_zone_radius() const
    {
      return fine_zone;
    }
    double
    graded_half_width() const
    {
      return fixed_half_width;
    }
    /// 'Grade for measured contact'; with_mesh_graded_for() clears it.
    bool
    grades_for_measured_contact() const
    {
      return measured_grading;
    }
    /// 'Graded mesh = conforming': the graded mesh halved without hanging
    /// nodes (a disk in 3D: extruded through graded layers).
    bool
    conforming_mesh() const
    {
      return conforming;
    }

    /// 'Layer refinement': how many times more a disk's layers in 3D are
    /// refined than its section (negative: coarser).
    int
    layer_refinement() const
    {
      return layer_levels;
    }

    /// Whether 'One-DOF law constant = finite size' (a sphere's derived D).
    bool
    finite_size_law_constant() const
    {
      return law_constant == "finite size";
    }
    /// The 'One-DOF law constant' but 'finite size': a disk's C ('exact':
    /// the centre-of-mass constant of @p nu2, 'fit', or a number), a
    /// sphere's D ('exact': 0, or a number).
    double
    fixed_law_constant(double nu2, bool sphere) const;

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
    double              incidence_angle = 0.;
    double              initial_spin    = 0.;
    std::vector<double> sweep_velocities;
    std::vector<double> sweep_poisson_ratios;
    std::vector<double> sweep_angles;
    std::vector<double> sweep_relaxation_times;
    std::vector<double> sweep_partner_radii;
    bool                error_estimate      = true;
    bool                resume_sweep        = true;
    unsigned int        contact_elements    = 12;
    double              mesh_grading        = 0.3;
    double              fine_zone           = default_fine_zone_radius;
    double              fixed_half_width    = 0.;
    bool                measured_grading    = false;
    bool                conforming          = false;
    int                 layer_levels        = 0;
    std::string         law_constant        = "exact";
    double              margin              = 0.2;
    unsigned int        output_interval     = 20;
    double              revolved_view_angle = 0.; ///< degrees; 0: none
    unsigned int        projected_modes     = 20;
  };
} // namespace DiskImpact
