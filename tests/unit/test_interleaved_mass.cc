// The product with the mass matrix through one scalar matrix for both
// components (InterleavedMass) against the product with M itself, on half
// disks with a symmetry plane.

#include "body/geometry.h"
#include "elasticity/constraint_map.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/interleaved_mass.h"
#include "half_disk.h"
#include "material/material.h"

#include <deal.II/distributed/tria.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <memory>

using namespace DiskImpact;

namespace
{
  /// The elasticity operator of degree @p degree on @p geometry, assembled
  /// for plane strain, with a massless edge zone of @p massless_radius
  /// around the contact point if positive.
  struct AssembledOperator
  {
    AssembledOperator(const BodyGeometry &geometry,
                      const unsigned int  degree,
                      const double        massless_radius = 0.)
        : triangulation(
            MPI_COMM_WORLD,
            dealii::Triangulation<2>::limit_level_difference_at_vertices)
        , op(degree)
    {
      geometry.create_triangulation(triangulation);
      op.setup(triangulation, geometry, true);
      if (massless_radius > 0.)
        op.set_massless_edge_zone(geometry.contact_point(), massless_radius);
      Material material;
      material.set(PlaneModel::plane_strain, 1., 0.3, 1., 0.);
      op.assemble(material);
    }
    dealii::parallel::distributed::Triangulation<2> triangulation;
    ElasticityOperator<2>                           op;
  };

  /// A field with every unconstrained entry nonzero and the constrained
  /// ones zero.
  dealii::PETScWrappers::MPI::Vector
  test_field(const ElasticityOperator<2> &op)
  {
    auto x = op.create_vector();
    for (const auto i : op.locally_owned_dofs())
      x(i) = std::sin(0.37 * i) + 2.;
    x.compress(dealii::VectorOperation::insert);
    op.get_constraints().set_zero(x);
    return x;
  }

  /// Largest |a_i - b_i| and largest |a_i| over this rank's entries.
  std::pair<double, double>
  difference_and_size(const dealii::PETScWrappers::MPI::Vector &a,
                      const dealii::PETScWrappers::MPI::Vector &b)
  {
    double difference = 0., size = 0.;
    for (const auto i : a.locally_owned_elements())
      {
        difference = std::max(difference, std::abs(a(i) - b(i)));
        size       = std::max(size, std::abs(a(i)));
      }
    return {difference, size};
  }
} // namespace

TEST_CASE("the mass product through one scalar matrix equals M's", "[fe]")
{
  // Cubic elements on the symmetry plane's constraints alone; quadratic
  // ones with hanging nodes too (the contact zone twice refined).
  const std::vector<std::pair<BodyGeometry, unsigned int>> cases{
    {half_disk(2), 3}, {half_disk(2, 2), 2}};
  for (const auto &[geometry, degree] : cases)
    {
      const AssembledOperator assembled(geometry, degree);
      const auto             &op          = assembled.op;
      const auto             &constraints = op.get_constraints();
      REQUIRE(constraints.n_constraints() > 4);
      const ConstraintMap   map(constraints,
                              op.locally_owned_dofs(),
                              MPI_COMM_WORLD);
      const InterleavedMass product(op.mass_matrix(), constraints, map);
      REQUIRE(product.scalar());

      const auto x        = test_field(op);
      auto       expected = op.create_vector(), y = op.create_vector();
      op.mass_matrix().vmult(expected, x);
      product.vmult(y, x);
      // Sums of up to a hundred terms of one sign, from entries an ulp
      // apart at most: a few ulps of the largest entry of M x.
      const auto [difference, size] = difference_and_size(y, expected);
      CHECK(size > 0.);
      CHECK(difference <= 16. * std::numeric_limits<double>::epsilon() * size);
      for (const auto i : op.locally_owned_dofs())
        if (constraints.is_constrained(i))
          CHECK(y(i) == 0.);
    }
}

TEST_CASE("a matrix that is not m ⊗ I2 keeps its own product", "[fe]")
{
  // With the massless edge zone some x-x and y-y entries of M differ (the
  // zone's mass is moved DoF by DoF); the stiffness matrix couples x with y.
  const AssembledOperator assembled(half_disk(2), 3, 0.2);
  const auto             &op = assembled.op;
  const auto              x  = test_field(op);
  const ConstraintMap     map(op.get_constraints(),
                          op.locally_owned_dofs(),
                          MPI_COMM_WORLD);
  for (const auto *matrix : {&op.mass_matrix(), &op.stiffness_matrix()})
    {
      const InterleavedMass product(*matrix, op.get_constraints(), map);
      CHECK_FALSE(product.scalar());
      auto expected = op.create_vector(), y = op.create_vector();
      matrix->vmult(expected, x);
      product.vmult(y, x);
      CHECK(difference_and_size(y, expected).first == 0.);
    }
}
