#pragma once

#include "body/geometry.h"

#include <deal.II/grid/tria.h>

#include <limits>
#include <vector>

namespace DiskImpact
{
  /**
   * The body of subsection Geometry in three dimensions ('Dimension = 3'),
   * centred on (R, 0, 0), touching the plane x = 0 at the origin as the
   * two-dimensional bodies do; whole, the sphere's half z >= 0
   * (has_symmetry_plane_z(), boundary id BoundaryIds::symmetry_z on its
   * plane), or the quarter y >= 0, z >= 0 (also has_symmetry_boundary(),
   * BoundaryIds::symmetry on y = 0).
   * - The sphere: deal.II's balanced ball (32 cells, 16 in the half, 8 in
   *   the quarter) with
   *   the surface as a spherical manifold and a transfinite interpolation
   *   in the cells next to it.
   * - The disk of thickness H about the z axis through the centre: the
   *   plane models' coarse disk extruded along z, the rim (BoundaryIds::
   *   curved) on a cylindrical manifold, the flat faces BoundaryIds::
   *   flat_faces.
   *
   * A mapping of the element's degree represents the curved surface to
   * that degree (boundary id BoundaryIds::curved). Throws an InputError if
   * the refined mesh would exceed about @p max_cells cells.
   */
  void
  create_solid_triangulation(
    const BodyGeometry       &geometry,
    dealii::Triangulation<3> &triangulation,
    double max_cells = std::numeric_limits<double>::infinity());

  /**
   * The disk of subsection Geometry in 3D made of @p section (its mesh in
   * the plane z = 0, with the boundary and manifold ids of
   * BodyGeometry::create_coarse_triangulation()) extruded through the
   * planes @p z (increasing; from 0 to H/2 for the quarter, from -H/2 to
   * H/2 for the whole disk), with the ids of create_solid_triangulation().
   */
  void
  extrude_disk(const BodyGeometry             &geometry,
               const dealii::Triangulation<2> &section,
               const std::vector<double>      &z,
               dealii::Triangulation<3>       &triangulation);
} // namespace DiskImpact
