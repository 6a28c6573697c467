// The axisymmetric weak form of the sphere on its meridian: the mass and
// strain energy of fields whose 3D values are known in closed form.

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "material/material.h"

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;

namespace
{
  /// u = a + e (x - c): a translation plus a uniform expansion about c.
  class AffineField : public dealii::Function<2>
  {
  public:
    AffineField(const dealii::Tensor<1, 2> &a,
                const double                e,
                const dealii::Point<2>     &c)
        : dealii::Function<2>(2)
        , a(a)
        , e(e)
        , c(c)
    {
    }
    double
    value(const dealii::Point<2> &x,
          const unsigned int      component) const override
    {
      return a[component] + e * (x[component] - c[component]);
    }

  private:
    dealii::Tensor<1, 2> a;
    double               e;
    dealii::Point<2>     c;
  };

  BodyGeometry
  sphere(const double radius)
  {
    dealii::ParameterHandler prm;
    BodyGeometry::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Body", "sphere");
    prm.set("Radius", std::to_string(radius));
    prm.set("Global refinements", "2");
    prm.leave_subsection();
    BodyGeometry geometry;
    geometry.parse_parameters(prm);
    return geometry;
  }
} // namespace

TEST_CASE("axisymmetric mass and strain energy of the sphere",
          "[axisymmetric][fe]")
{
  const double R = 1.5, E = 2., nu = 0.3, rho = 3.;
  const auto   geometry = sphere(R);
  REQUIRE(geometry.is_axisymmetric());
  REQUIRE(geometry.has_symmetry_boundary());
  Material material;
  material.set(PlaneModel::axisymmetric, E, nu, rho);

  dealii::parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
  geometry.create_triangulation(triangulation);
  ElasticityOperator<2> op(4);
  op.setup(triangulation, geometry);
  op.assemble(material);

  const double volume = 4. / 3. * M_PI * R * R * R;
  auto         u = op.create_vector(), ku = op.create_vector();
  auto energy = [&](const dealii::PETScWrappers::MPI::SparseMatrix &matrix) {
    matrix.vmult(ku, u);
    return 0.5 * (u * ku);
  };

  // A unit translation along the axis: kinetic energy of a unit velocity
  // m / 2 = rho V / 2, and no strain.
  dealii::Tensor<1, 2> axial;
  axial[0] = 1.;
  dealii::VectorTools::interpolate(op.get_mapping(),
                                   op.get_dof_handler(),
                                   AffineField(axial, 0., geometry.center()),
                                   u);
  CHECK(energy(op.mass_matrix()) == Approx(0.5 * rho * volume).epsilon(1e-9));
  CHECK(energy(op.stiffness_matrix()) == Approx(0.).margin(1e-12));

  // A uniform expansion e about the centre: eps = e 1 in 3D (the hoop
  // strain u_r / r = e included), strain energy 9/2 K e^2 V with the bulk
  // modulus K = E / (3 (1 - 2 nu)); the centre of mass stays.
  const double e = 1e-2, K = E / (3. * (1. - 2. * nu));
  dealii::VectorTools::interpolate(op.get_mapping(),
                                   op.get_dof_handler(),
                                   AffineField(dealii::Tensor<1, 2>(),
                                               e,
                                               geometry.center()),
                                   u);
  CHECK(energy(op.stiffness_matrix()) ==
        Approx(4.5 * K * e * e * volume).epsilon(1e-9));
  CHECK(op.mean_displacement(op.create_ghosted(u)).norm() ==
        Approx(0.).margin(1e-12));
}
