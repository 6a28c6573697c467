#pragma once

#include "material/material.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <limits>

namespace DiskImpact
{
  class BodyGeometry;

  /**
   * Subsection "Partner": what the body collides with. 'wall' is the rigid
   * wall of subsection Contact. 'body' is a second deformable body of the
   * same kind (disk or sphere), plane model and domain, with its own radius
   * R2 and material, on the other side of the plane x = 0: its centre is at
   * (-gap - R2, offset), so with gap = offset = 0 both touch at the origin
   * and meet head-on along the impact axis y = 0.
   *
   * The pair's mesh holds both bodies as separate pieces (no shared
   * vertex): the body's cells have material id 0, the partner's 1; the
   * partner's curved edge has boundary id BoundaryIds::partner_curved and
   * manifold id partner_manifold_id. Both are graded toward the origin by
   * the same rules.
   */
  class Partner
  {
  public:
    enum class Kind
    {
      wall,
      body
    };

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse the subsection; the partner's 'Plane model' (empty: the
    /// body's) and body kind must match @p geometry and @p body_material.
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const BodyGeometry       &geometry,
                     const Material           &body_material);

    bool
    is_body() const;
    /// R2.
    double
    radius() const;
    /// The same partner with the radius @p radius (a sweep's point);
    /// throws an InputError if it is not positive.
    Partner
    with_radius(double radius) const;
    const Material &
    material() const;
    /// (-gap - R2, 0).
    dealii::Point<2>
    center() const;
    /// The distance between the two undeformed surfaces along the axis.
    double
    gap() const;

    /**
     * Both bodies' coarse meshes as one triangulation with their ids and
     * manifolds, refined as BodyGeometry::create_triangulation() refines
     * one body; throws an InputError if it would exceed about @p max_cells
     * cells.
     */
    void
    create_pair_triangulation(
      const BodyGeometry       &geometry,
      dealii::Triangulation<2> &triangulation,
      double max_cells = std::numeric_limits<double>::infinity()) const;

  private:
    Kind     kind           = Kind::wall;
    double   partner_radius = 1.;
    double   partner_gap    = 0.;
    Material partner_material;
  };
} // namespace DiskImpact
