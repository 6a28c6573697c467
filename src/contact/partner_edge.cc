#include "contact/partner_edge.h"

#include "body/geometry.h"
#include "contact/constrained_row.h"
#include "elasticity/elasticity_operator.h"

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <boost/math/tools/roots.hpp>

#include <map>

namespace DiskImpact
{
  using namespace dealii;

  std::vector<std::optional<PartnerEdgePoint>>
  locate_on_partner_edge(const ElasticityOperator<2> &op,
                         const RigidWall<2>          &wall,
                         const std::vector<Point<2>> &points)
  {
    const auto                          &dof_handler = op.get_dof_handler();
    const auto                          &fe          = dof_handler.get_fe();
    const auto                          &mapping     = op.get_mapping();
    const auto                          &constraints = op.get_constraints();
    const auto                          &n           = wall.normal;
    const Tensor<1, 2>                   along({-n[1], n[0]});
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());

    // This rank's answers, flattened: index, gap0, the number of entries,
    // then (DoF, value) pairs.
    std::vector<double> local;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary() ||
                cell->face(f)->boundary_id() != BoundaryIds::partner_curved)
              continue;
            // The face in the unit cell, s in [0, 1], and its mapped image.
            const Point<2> v0 = GeometryInfo<2>::unit_cell_vertex(
              GeometryInfo<2>::face_to_cell_vertices(f, 0));
            const Point<2> v1 = GeometryInfo<2>::unit_cell_vertex(
              GeometryInfo<2>::face_to_cell_vertices(f, 1));
            const auto unit = [&](const double s) {
              return Point<2>(v0 + s * (v1 - v0));
            };
            const auto real = [&](const double s) {
              return mapping.transform_unit_to_real_cell(cell, unit(s));
            };
            const Point<2> x0 = real(0.), x1 = real(1.);
            for (unsigned int k = 0; k < points.size(); ++k)
              {
                const auto offset = [&](const double s) {
                  return (real(s) - points[k]) * along;
                };
                const double o0 = (x0 - points[k]) * along;
                const double o1 = (x1 - points[k]) * along;
                if (o0 * o1 > 0.)
                  continue;
                double s = o0 == 0. ? 0. : 1.;
                if (o0 != 0. && o1 != 0.)
                  {
                    std::uintmax_t iterations = 100;
                    const auto     bracket = boost::math::tools::toms748_solve(
                      offset,
                      0.,
                      1.,
                      o0,
                      o1,
                      boost::math::tools::eps_tolerance<double>(52),
                      iterations);
                    s = 0.5 * (bracket.first + bracket.second);
                  }
                const Point<2> x2   = real(s);
                const double   gap0 = (points[k] - x2) * n;
                FEValues<2>    values(mapping,
                                   fe,
                                   Quadrature<2>(
                                     std::vector<Point<2>>{unit(s)}),
                                   update_values);
                values.reinit(cell);
                cell->get_dof_indices(dof_indices);
                ConstrainedRow row;
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  add_to_row(constraints,
                             dof_indices[i],
                             -(values[displacement].value(i, 0) * n),
                             row);
                local.insert(local.end(),
                             {static_cast<double>(k),
                              gap0,
                              static_cast<double>(row.size())});
                for (const auto &[dof, b] : row)
                  local.insert(local.end(), {static_cast<double>(dof), b});
              }
          }

    // The line meets the partner's edge twice: keep the side facing the
    // body, the smallest gap (a point on a vertex is found on both its
    // faces, with the same x2: the first in rank order stays).
    std::vector<std::optional<PartnerEdgePoint>> result(points.size());
    for (const auto &part :
         Utilities::MPI::all_gather(dof_handler.get_communicator(), local))
      for (std::size_t k = 0; k < part.size();)
        {
          const auto index     = static_cast<std::size_t>(part[k]);
          const auto n_entries = static_cast<std::size_t>(part[k + 2]);
          if (!result[index] || part[k + 1] < result[index]->gap0)
            {
              PartnerEdgePoint point;
              point.gap0 = part[k + 1];
              for (std::size_t e = 0; e < n_entries; ++e)
                point.row.emplace_back(static_cast<types::global_dof_index>(
                                         part[k + 3 + 2 * e]),
                                       part[k + 4 + 2 * e]);
              result[index] = std::move(point);
            }
          k += 3 + 2 * n_entries;
        }
    return result;
  }
} // namespace DiskImpact
