#pragma once

#include <deal.II/base/parameter_handler.h>

namespace DiskImpact
{
  /**
   * Subsection "Impact convergence": how a convergence study of epsilon
   * refines the impact of the parameter file (ImpactConvergenceStudy runs
   * it): the levels of each sequence, a target error with the largest
   * levels it may add, and the split of the last difference into its time
   * step and mesh parts.
   */
  struct ImpactConvergenceParameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The number of mesh levels of the finest run the study may make.
    unsigned int
    finest_mesh_levels() const
    {
      return target_error > 0. ? largest_mesh_levels : mesh_levels;
    }

    unsigned int mesh_levels           = 3;
    unsigned int time_step_levels      = 3;
    unsigned int penalty_levels        = 3;
    double       target_error          = 0.; ///< 0: exactly mesh_levels
    unsigned int largest_mesh_levels   = 3;
    bool         separate_time_step    = false;
    unsigned int largest_time_halvings = 0;
    unsigned int degree_levels_from    = 0;  ///< 0: every level refines h
    double       halve_first_above     = 0.; ///< 0: never
  };
} // namespace DiskImpact
