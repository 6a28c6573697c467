#pragma once

#include "reference/free_disk_modes.h"

#include <deal.II/lac/petsc_vector.h>

#include <vector>

namespace DiskImpact
{
  class ElasticityOperator;
  class DiskGeometry;

  /**
   * Angular harmonic content of a displacement field on the curved edge:
   * power of u_r and u_phi in cos(n phi), sin(n phi) for n = 0 ... n_max,
   * each normalised by the integral of cos^2 or sin^2 over the edge. On the
   * half circle of a half disk only the symmetric parts count: u_r in
   * cos(n phi), u_phi in sin(n phi).
   */
  struct HarmonicContent
  {
    std::vector<double> radial_power;
    std::vector<double> tangential_power;

    /// The angular order carrying most of the power.
    unsigned int
    dominant_order() const;
    /// Share of the total power in dominant_order().
    double
    dominant_fraction() const;
  };

  /// A computed mode's label and how clearly its edge motion shows it.
  struct LabelledMode
  {
    Reference::ModeLabel label;
    double               harmonic_fraction = 1.;
  };

  /// The harmonic content of @p ghosted_displacement on the curved edge.
  HarmonicContent
  compute_boundary_harmonics(
    const ElasticityOperator                 &op,
    const DiskGeometry                       &geometry,
    const dealii::PETScWrappers::MPI::Vector &ghosted_displacement,
    unsigned int                              n_max);

  /**
   * Label modes sorted by eigenvalue: rigid below @p rigid_eigenvalue;
   * otherwise n from the dominant harmonic, the family (radial or
   * torsional for n = 0, mixed otherwise) from which component carries it,
   * and l by counting the modes of the same (n, family) met so far, each
   * n >= 1 counted once per orientation (twice on the full disk).
   */
  std::vector<LabelledMode>
  label_modes(const std::vector<double>          &eigenvalues,
              const std::vector<HarmonicContent> &harmonics,
              double                              rigid_eigenvalue,
              bool                                half_disk);
} // namespace DiskImpact
