#pragma once

#include "material/material.h"

#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/petsc_vector.h>

#include <vector>

namespace DiskImpact
{
  /// The largest von Mises stress of a field and the point where it is.
  struct StressPeak
  {
    double           von_mises = 0.;
    dealii::Point<2> location;
  };

  /**
   * The largest von Mises stress of the elastic displacement @p u (ghosted)
   * on a section (a disk's, or a sphere's meridian with its hoop stress),
   * sampled on an iterated Gauss rule (6 x 6 points per cell) in every
   * locally owned cell (with @p reach > 0 only the cells within @p reach
   * of @p center); the largest over all ranks and its point, the same on
   * every rank. Cells with material id i take @p materials[i]. Where a
   * Hertz contact first yields, a smooth subsurface maximum, the sampling
   * misses the peak by O(h^2) of its curvature.
   */
  StressPeak
  largest_von_mises(const dealii::Mapping<2>                 &mapping,
                    const dealii::DoFHandler<2>              &dof_handler,
                    const std::vector<Material>              &materials,
                    const dealii::PETScWrappers::MPI::Vector &u,
                    const dealii::Point<2> &center = dealii::Point<2>(),
                    double                  reach  = 0.);
} // namespace DiskImpact
