#pragma once

#include "contact/contact.h"

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <optional>
#include <utility>
#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;

  /// A point of a collision partner's edge facing a point x of the body's
  /// edge (locate_on_partner_edge()).
  struct PartnerEdgePoint
  {
    /// (x - x2) . n: the undeformed gap between the two edges along n.
    double gap0 = 0.;
    /// (DoF, -n . phi_i(x2)): the row of -n . u(x2), hanging-node
    /// constraints resolved.
    std::vector<std::pair<dealii::types::global_dof_index, double>> row;
  };

  /**
   * For each point x of @p points (the same list on every rank): the point
   * x2 of the partner's curved edge (boundary id
   * BoundaryIds::partner_curved) on the line through x along the contact
   * normal n = @p wall.normal, or nothing if that line misses the part of
   * the edge facing the body. x2 lies on the edge as the mapping of degree
   * k describes it (found on its faces by Brent's method), so that two
   * mirror-image meshes pair their points exactly. Small strains: the gap
   * of the pair is g = gap0 + n . u1(x) - n . u2(x2), the contact acting
   * along n on both bodies. Collective; every rank returns the same answer.
   */
  std::vector<std::optional<PartnerEdgePoint>>
  locate_on_partner_edge(const ElasticityOperator<2>         &op,
                         const RigidWall<2>                  &wall,
                         const std::vector<dealii::Point<2>> &points);
} // namespace DiskImpact
