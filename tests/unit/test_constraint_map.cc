// The constraints as a matrix (ConstraintMap) against deal.II's
// AffineConstraints on a mesh with hanging nodes and a symmetry plane.

#include "body/geometry.h"
#include "elasticity/constraint_map.h"
#include "elasticity/elasticity_operator.h"
#include "half_disk.h"

#include <deal.II/distributed/tria.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace DiskImpact;

namespace
{
  /// Largest |a_i - b_i| over this rank's entries.
  double
  largest_difference(const dealii::PETScWrappers::MPI::Vector &a,
                     const dealii::PETScWrappers::MPI::Vector &b)
  {
    double difference = 0.;
    for (const auto i : a.locally_owned_elements())
      difference = std::max(difference, std::abs(a(i) - b(i)));
    return difference;
  }
} // namespace

TEST_CASE("constraints as a matrix: distribute and set_zero as deal.II's",
          "[fe]")
{
  const BodyGeometry                              geometry = half_disk(1, 3);
  dealii::parallel::distributed::Triangulation<2> triangulation(
    MPI_COMM_WORLD,
    dealii::Triangulation<2>::limit_level_difference_at_vertices);
  geometry.create_triangulation(triangulation);
  ElasticityOperator<2> op(3);
  op.setup(triangulation, geometry);

  // The operator's constraints (homogeneous) and a copy with an
  // inhomogeneity on every constrained line.
  const auto                       &homogeneous = op.get_constraints();
  dealii::AffineConstraints<double> inhomogeneous;
  inhomogeneous.copy_from(homogeneous);
  unsigned int n_constrained = 0;
  for (const auto &line : homogeneous.get_lines())
    {
      inhomogeneous.set_inhomogeneity(line.index, 0.01 * (line.index % 7));
      ++n_constrained;
    }
  REQUIRE(n_constrained > 10);

  for (const dealii::AffineConstraints<double> *constraints :
       {&homogeneous,
        static_cast<const dealii::AffineConstraints<double> *>(&inhomogeneous)})
    {
      const ConstraintMap map(*constraints,
                              op.locally_owned_dofs(),
                              MPI_COMM_WORLD);
      auto                x = op.create_vector();
      for (const auto i : op.locally_owned_dofs())
        x(i) = std::sin(0.37 * i) + 2.;
      x.compress(dealii::VectorOperation::insert);

      auto expected = x, mapped = x;
      constraints->distribute(expected);
      map.distribute(mapped);
      // Sums of a few terms of size <= 3, in another order: a few ulps.
      CHECK(largest_difference(mapped, expected) <=
            8. * 3. * std::numeric_limits<double>::epsilon());
      // Something was distributed: the lines changed x.
      CHECK(largest_difference(expected, x) > 0.01);

      expected = x;
      mapped   = x;
      constraints->set_zero(expected);
      map.set_zero(mapped);
      CHECK(largest_difference(mapped, expected) == 0.);
    }
}
