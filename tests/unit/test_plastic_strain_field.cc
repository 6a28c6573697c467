// The plastic strain field of an elastic-plastic body: under a uniform
// strain every point returns to the same state as J2ReturnMapping alone,
// and the field's force, plastic work and energy are that state's values
// times the body's volume (plane strain, and the sphere with its hoop
// strain).

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/plastic_strain_field.h"
#include "half_disk.h"
#include "material/j2_return_mapping.h"
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
  /// u = (a (x - c_x), b y): uniform strains a, b (and hoop strain b on
  /// an axisymmetric body), u_y = 0 on the axis of symmetry y = 0.
  class StretchField : public dealii::Function<2>
  {
  public:
    StretchField(const double a, const double b, const double c_x)
        : dealii::Function<2>(2)
        , a(a)
        , b(b)
        , c_x(c_x)
    {
    }
    double
    value(const dealii::Point<2> &x,
          const unsigned int      component) const override
    {
      return component == 0 ? a * (x[0] - c_x) : b * x[1];
    }

  private:
    double a, b, c_x;
  };

  BodyGeometry
  sphere()
  {
    dealii::ParameterHandler prm;
    BodyGeometry::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Body", "sphere");
    prm.set("Global refinements", "1");
    prm.leave_subsection();
    BodyGeometry geometry;
    geometry.parse_parameters(prm);
    return geometry;
  }

  /// Two loading steps of the field u = s (a, b) at s = 1 and 2 against
  /// the return mapping at one point.
  void
  check_uniform_strain(const BodyGeometry &geometry,
                       Material            material,
                       const double        hoop_factor)
  {
    const double Y = 2e-3, H = 0.1, a = -6e-3, b = 1e-3;
    material.set_plasticity(Y, H);
    dealii::parallel::distributed::Triangulation<2> triangulation(
      MPI_COMM_WORLD);
    geometry.create_triangulation(triangulation);
    ElasticityOperator<2> op(2);
    op.setup(triangulation, geometry);
    op.assemble(material);
    const double volume = op.volume();

    PlasticStrainField<2>  field(op, {material});
    const J2ReturnMapping  point(material.lame_lambda_3d(),
                                material.shear_modulus_3d(),
                                Y,
                                H);
    auto                   u = op.create_vector(), force = op.create_vector();
    J2ReturnMapping::State state;
    dealii::SymmetricTensor<2, 3> stress;
    for (const double s : {1., 2.})
      {
        dealii::VectorTools::interpolate(op.get_mapping(),
                                         op.get_dof_handler(),
                                         StretchField(s * a,
                                                      s * b,
                                                      geometry.center()[0]),
                                         u);
        dealii::SymmetricTensor<2, 3> strain;
        strain[0][0]      = s * a;
        strain[1][1]      = s * b;
        strain[2][2]      = hoop_factor * s * b;
        const auto update = point.update(strain, state);
        REQUIRE(update.yielded);

        field.evaluate(u, force);
        CHECK(field.n_yielding_points() > 0);
        // f_p . u = int eps : C : eps_p dV.
        const double expected_force_work =
          strain * point.elastic_stress(update.state.plastic_strain) * volume;
        CHECK((force * u) == Approx(expected_force_work).epsilon(1e-10));
        // The plastic work by the trapezoidal rule in the stress.
        const double expected_work =
          (update.state.plastic_strain - state.plastic_strain) *
          (0.5 * (stress + update.stress)) * volume;
        CHECK(field.accept() == Approx(expected_work).epsilon(1e-10));
        CHECK(field.plastic_strain_energy() ==
              Approx(0.5 * update.state.plastic_strain *
                     point.elastic_stress(update.state.plastic_strain) * volume)
                .epsilon(1e-10));
        CHECK(field.largest_equivalent_plastic_strain() ==
              Approx(update.state.equivalent_plastic_strain).epsilon(1e-10));
        state  = update.state;
        stress = update.stress;
      }
  }
} // namespace

TEST_CASE("plastic strain field: uniform strain in plane strain",
          "[plasticity][fe]")
{
  Material material;
  material.set(PlaneModel::plane_strain, 1., 0.3, 1.);
  check_uniform_strain(half_disk(1), material, 0.);
}

TEST_CASE("plastic strain field: uniform strain in the axisymmetric sphere",
          "[plasticity][fe]")
{
  Material material;
  material.set(PlaneModel::axisymmetric, 1., 0.3, 1.);
  check_uniform_strain(sphere(), material, 1.);
}

TEST_CASE("plastic strain field: plane stress is refused", "[plasticity]")
{
  Material material;
  material.set(PlaneModel::plane_stress, 1., 0.3, 1.);
  material.set_plasticity(1e-3, 0.);
  dealii::parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
  half_disk(0).create_triangulation(triangulation);
  ElasticityOperator<2> op(2);
  op.setup(triangulation, half_disk(0));
  op.assemble(material);
  CHECK_THROWS(PlasticStrainField<2>(op, {material}));
}
