#pragma once

#include <deal.II/grid/tria.h>

#include <vector>

namespace DiskImpact
{
  /**
   * A graded quadrilateral mesh without hanging nodes, made from a mesh
   * refined locally (with hanging nodes) by halving every element once:
   * - a cell without hanging nodes on its edges splits into its four
   *   children (edge midpoints and centre);
   * - a cell with hanging nodes is fanned from its centre into triangles
   *   (one per edge piece), each split into three quadrilaterals at the
   *   midpoints of its edges and its centroid.
   * Every edge gets its midpoint from both sides, so the result is
   * conforming. The boundary ids and manifolds of @p refined carry over
   * (a curved edge's midpoint lies on its manifold). @p conforming must be
   * empty; it may be distributed.
   */
  void
  split_into_conforming_mesh(const dealii::Triangulation<2> &refined,
                             dealii::Triangulation<2>       &conforming);

  /**
   * The z coordinates 0 = z_0 < ... < z_n = @p height of layers that are
   * thinnest at z = height (a face) and thicken toward z = 0 as a graded
   * mesh's cells grow away from the contact: a layer starting at distance
   * d from the face is finest + grading * max(0, d - fine_zone) thick, at
   * most @p largest; all are scaled by the same factor to fill the height.
   */
  std::vector<double>
  layers_graded_toward_face(double height,
                            double finest,
                            double grading,
                            double fine_zone,
                            double largest);
} // namespace DiskImpact
