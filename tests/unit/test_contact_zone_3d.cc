// The wall's contact zone on the quarter sphere in 3D: its points' shares
// of the surface, the nodes shared by faces merged, the gap and tangential
// rows of a rigid motion, and the coordinate along the wall.

#include "body/geometry.h"
#include "body/solid_geometry.h"
#include "contact/contact.h"
#include "contact/contact_operator.h"
#include "contact/contact_zone.h"
#include "contact/penalty_law.h"
#include "elasticity/elasticity_operator.h"
#include "interpolated_field.h"
#include "material/material.h"

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace DiskImpact;

namespace
{
  /// The quarter sphere of radius 1 (Q2, one global refinement) touching
  /// the wall x = 0 at the origin.
  struct QuarterSphere
  {
    QuarterSphere()
        : triangulation(MPI_COMM_WORLD)
        , op(2)
    {
      dealii::ParameterHandler prm;
      BodyGeometry::declare_parameters(prm);
      ContactParameters::declare_parameters(prm);
      prm.enter_subsection("Geometry");
      prm.set("Body", "sphere");
      prm.set("Dimension", "3");
      prm.set("Domain", "quarter sphere");
      prm.set("Global refinements", "1");
      prm.leave_subsection();
      geometry.parse_parameters(prm);
      contact.parse_parameters(prm);
      create_solid_triangulation(geometry, triangulation);
      op.setup(triangulation, geometry);
      Material material;
      material.set(PlaneModel::plane_strain, 1., 0.3, 1., 0.);
      op.assemble(material);
    }

    /// The candidates within @p bound of the wall; the exact constraint's
    /// nodes with @p nodal, else the penalty law's quadrature points.
    ContactZone
    zone(const double bound, const bool nodal) const
    {
      std::shared_ptr<const ContactLaw> law;
      if (!nodal)
        law = contact.law({1., smallest_edge_face(op), 1.});
      return ContactZone(op,
                         contact.wall<3>(),
                         law,
                         dealii::Point<3>(1., 0., 0.),
                         bound,
                         false,
                         true);
    }

    /// A field on the DoFs, constraints applied.
    dealii::PETScWrappers::MPI::Vector
    interpolate(const dealii::Function<3> &f) const
    {
      return interpolated_field(op, f);
    }

    BodyGeometry                                    geometry;
    ContactParameters                               contact;
    dealii::parallel::distributed::Triangulation<3> triangulation;
    ElasticityOperator<3>                           op;
  };

  /// The values of @p u on the zone's candidate DoFs.
  dealii::Vector<double>
  on_candidates(const ContactZone                        &zone,
                const dealii::PETScWrappers::MPI::Vector &u)
  {
    dealii::Vector<double> values(zone.candidate_dofs().size());
    for (unsigned int i = 0; i < values.size(); ++i)
      values[i] = u[zone.candidate_dofs()[i]];
    return values;
  }
} // namespace

TEST_CASE("The 3D contact zone's shares are the quarter sphere's surface",
          "[3d][contact]")
{
  const QuarterSphere body;
  // A bound beyond the diameter takes every face of the surface. The
  // nodes' shares integrate Lagrange polynomials that sum to one with the
  // penalty's Gauss rule: the two sums are one area to rounding, a node
  // counted twice or lost (merging) would show. It is the quarter sphere's
  // pi R^2 to the accuracy of the Q2 mapping on 24 faces (8.1e-5).
  std::vector<double> areas;
  for (const bool nodal : {true, false})
    {
      const ContactZone zone = body.zone(3., nodal);
      double            area = 0.;
      for (unsigned int i = 0; i < zone.n_points(); ++i)
        area += zone.share(i);
      areas.push_back(area);
      const dealii::Vector<double> zero(zone.candidate_dofs().size());
      const auto                   gaps         = zone.point_gaps(zero);
      double                       smallest_gap = 1.;
      for (unsigned int i = 0; i < zone.n_points(); ++i)
        smallest_gap = std::min(smallest_gap, gaps[i]);
      // The pole is a node (it touches the wall), not a Gauss point.
      if (nodal)
        CHECK(smallest_gap == Approx(0.).margin(1e-12));
      else
        CHECK(smallest_gap > 0.);
    }
  CHECK(areas[0] == Approx(areas[1]).epsilon(1e-12));
  CHECK(areas[0] == Approx(M_PI).epsilon(3e-4));
}

TEST_CASE("The 3D contact zone merges nodes and reads rigid motions",
          "[3d][contact]")
{
  const QuarterSphere body;
  const ContactZone   nodal = body.zone(0.3, true);
  // The nodes of the surface within the bound, each once: no two points
  // at one place (their coordinates along the wall and gaps all differ
  // or they are distinct nodes on one ring).
  const dealii::Vector<double> zero(nodal.candidate_dofs().size());
  const auto                   gap0 = nodal.point_gaps(zero);
  for (unsigned int i = 0; i < nodal.n_points(); ++i)
    {
      // On the sphere x = 1 - sqrt(1 - t^2): the gap and the coordinate
      // along the wall of a surface point.
      const double t = nodal.coordinate_along_wall(i);
      CHECK(gap0[i] == Approx(1. - std::sqrt(1. - t * t)).margin(1e-5));
    }

  // A rigid translation (0.01, 0.02, 0.03): every gap grows by 0.01, the
  // tangential rows read 0.02 and 0.03 (u_y = u_z = 0 on the planes of
  // symmetry leave those out where the constraints hold).
  const auto u = body.interpolate(
    dealii::Functions::ConstantFunction<3>(std::vector<double>{0.01, 0., 0.}));
  const auto gaps = nodal.point_gaps(on_candidates(nodal, u));
  for (unsigned int i = 0; i < nodal.n_points(); ++i)
    CHECK(gaps[i] - gap0[i] == Approx(0.01).margin(1e-12));
  const auto v = body.interpolate(dealii::Functions::ConstantFunction<3>(
    std::vector<double>{0., 0.02, 0.03}));
  for (unsigned int i = 0; i < nodal.n_points(); ++i)
    for (unsigned int direction = 0; direction < 2; ++direction)
      {
        double along = 0.;
        for (const auto &[dof, b] : nodal.tangential_row(i, direction))
          along += b * v[dof];
        const bool on_plane =
          nodal.tangential_row(i, direction).empty() || along == 0.;
        if (!on_plane)
          CHECK(along == Approx(direction == 0 ? 0.02 : 0.03).margin(1e-12));
      }
}
