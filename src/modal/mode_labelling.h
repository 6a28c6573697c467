#pragma once

#include "reference/free_body_modes.h"

#include <deal.II/lac/petsc_vector.h>

#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;
  class BodyGeometry;

  /**
   * Angular harmonic content of a displacement field on the curved edge:
   * power of u_r and u_phi in cos(n phi), sin(n phi) for n = 0 ... n_max,
   * each normalised by the integral of cos^2 or sin^2 over the edge. On the
   * half circle of a half disk only the symmetric parts count: u_r in
   * cos(n phi), u_phi in sin(n phi).
   *
   * On a sphere (axisymmetric section) the harmonics are Legendre's: u_r in
   * P_n(cos theta), u_theta in dP_n/dtheta, over the surface
   * (sin theta dtheta), theta the polar angle from the axis.
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
    /// Share of the total power in the even orders; for a sphere the
    /// z-parity about the equator (P_n(-x) = (-1)^n P_n(x)).
    double
    even_order_fraction() const;
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
    const ElasticityOperator<2>              &op,
    const BodyGeometry                       &geometry,
    const dealii::PETScWrappers::MPI::Vector &ghosted_displacement,
    unsigned int                              n_max);

  /**
   * Label modes sorted by eigenvalue: rigid below @p rigid_eigenvalue;
   * otherwise n from the dominant harmonic, the family (radial or
   * torsional for n = 0, @p coupled_family otherwise: mixed on a disk,
   * spheroidal on a sphere) from which component carries it, and l by
   * counting the modes of the same (n, family) met so far, each n >= 1
   * counted once per orientation (twice on the full disk).
   */
  /// The family of the modes that couple both components: mixed on a disk,
  /// spheroidal on a sphere.
  Reference::ModeFamily
  coupled_family(const BodyGeometry &geometry);

  std::vector<LabelledMode>
  label_modes(
    const std::vector<double>          &eigenvalues,
    const std::vector<HarmonicContent> &harmonics,
    double                              rigid_eigenvalue,
    bool                                half_domain,
    Reference::ModeFamily coupled_family = Reference::ModeFamily::mixed);
} // namespace DiskImpact
