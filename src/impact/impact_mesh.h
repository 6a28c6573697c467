#pragma once

#include <deal.II/grid/tria.h>

#include <limits>

namespace DiskImpact
{
  struct Parameters;

  /// The Hertz half-width at the largest force the 1-DOF model expects
  /// [length]: the contact zone the impact's mesh is graded for.
  double
  largest_half_width(const Parameters &parameters);

  /// The half-width the mesh is graded for [length]: 'Graded half-width'
  /// if set, else largest_half_width().
  double
  graded_width(const Parameters &parameters);

  /// The fine zone's radius over graded_width(): 'Fine zone radius', and
  /// as far again as the contact moves along the edge while the body
  /// turns (contact_drift()).
  double
  fine_zone_factor(const Parameters &parameters);

  /// The impact's mesh: the geometry's (with a partner body both bodies'),
  /// graded toward the contact point; throws an InputError if it would
  /// exceed about @p max_cells cells.
  template <int dim>
  void
  create_impact_mesh(
    const Parameters           &parameters,
    dealii::Triangulation<dim> &triangulation,
    double max_cells = std::numeric_limits<double>::infinity());
} // namespace DiskImpact
