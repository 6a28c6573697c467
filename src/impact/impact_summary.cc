#include "impact/impact_summary.h"

#include "output/csv_table.h"

namespace DiskImpact
{
  void
  write_summary(const ImpactSummary &s, const std::string &filename)
  {
    summary_table(s).write(filename);
  }

  CsvTable
  summary_table(const ImpactSummary &s)
  {
    CsvTable table({"velocity",
                    "epsilon",
                    "contact_time",
                    "delta_max",
                    "force_max",
                    "energy_error",
                    "steps",
                    "newton_iterations",
                    "impulse_error",
                    "time_step",
                    "n_dofs",
                    "factorizations",
                    "triangular_solves",
                    "one_dof_contact_time",
                    "one_dof_delta_max",
                    "alpha",
                    "one_dof_epsilon",
                    "one_dof_epsilon_overlap",
                    "vibration_fraction",
                    "partner_vibration_fraction",
                    "momentum_error",
                    "one_dof_epsilon_unloading",
                    "ramirez_u",
                    "peak_memory_mb",
                    "angle",
                    "friction",
                    "v_tangential_initial",
                    "v_tangential_final",
                    "tangential_restitution",
                    "spin_initial",
                    "spin_final",
                    "v_contact_initial",
                    "v_contact_final",
                    "contact_point_restitution",
                    "rebound_angle",
                    "psi_incident",
                    "psi_rebound",
                    "friction_work",
                    "rotation_in_contact",
                    "tangential_impulse_error",
                    "angular_impulse_error",
                    "von_mises_max",
                    "von_mises_depth",
                    "plastic_work",
                    "plastic_strain_max",
                    "plastic_iterations",
                    "tangent_factorizations",
                    "contact_half_width_max",
                    "graded_half_width"});
    table.start_row();
    for (const double value : {s.velocity,
                               s.epsilon,
                               s.contact_time,
                               s.delta_max,
                               s.force_max,
                               s.energy_error})
      table.add(value);
    table.add(s.steps);
    table.add(s.newton_iterations);
    table.add(s.impulse_error);
    table.add(s.time_step);
    table.add(s.n_dofs);
    table.add(s.factorizations);
    table.add(s.triangular_solves);
    table.add(s.one_dof_contact_time);
    table.add(s.one_dof_delta_max);
    table.add(s.schwager_alpha);
    table.add(s.one_dof_epsilon);
    table.add(s.one_dof_epsilon_overlap);
    table.add(s.vibration_fraction);
    table.add(s.partner_vibration_fraction);
    table.add(s.momentum_error);
    table.add(s.one_dof_epsilon_unloading);
    table.add(s.ramirez_u);
    table.add(s.peak_memory_mb);
    const ObliqueSummary &o = s.oblique;
    for (const double value : {s.angle,
                               s.friction,
                               o.v_tangential_initial,
                               o.v_tangential_final,
                               o.tangential_restitution(),
                               o.spin_initial,
                               o.spin_final,
                               o.v_contact_initial,
                               o.v_contact_final,
                               o.contact_point_restitution(),
                               o.rebound_angle,
                               o.psi_incident,
                               o.psi_rebound,
                               o.friction_work,
                               o.rotation_in_contact,
                               o.tangential_impulse_error,
                               o.angular_impulse_error,
                               s.von_mises_max,
                               s.von_mises_depth,
                               s.plastic_work,
                               s.plastic_strain_max})
      table.add(value);
    table.add(s.plastic_iterations);
    table.add(s.tangent_factorizations);
    table.add(s.contact_half_width_max);
    table.add(s.graded_half_width);
    return table;
  }
} // namespace DiskImpact
