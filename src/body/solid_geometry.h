#pragma once

#include "body/geometry.h"

#include <deal.II/grid/tria.h>

#include <limits>

namespace DiskImpact
{
  /**
   * The body of subsection Geometry in three dimensions ('Dimension = 3'):
   * the whole sphere of radius R centred at (R, 0, 0), touching the plane
   * x = 0 at the origin as the two-dimensional bodies do. Its coarse mesh
   * is deal.II's balanced ball (32 cells) with the sphere's surface as a
   * spherical manifold and a transfinite interpolation in the cells next to
   * it, so that a mapping of the element's degree represents the surface
   * to that degree; boundary id BoundaryIds::curved on the whole surface.
   * Throws an InputError if the refined mesh would exceed about
   * @p max_cells cells.
   */
  void
  create_solid_triangulation(
    const BodyGeometry       &geometry,
    dealii::Triangulation<3> &triangulation,
    double max_cells = std::numeric_limits<double>::infinity());

  /// The cells of the sphere's mesh after @p refinements global
  /// refinements: 32 8^refinements.
  double
  solid_sphere_cells(unsigned int refinements);
} // namespace DiskImpact
