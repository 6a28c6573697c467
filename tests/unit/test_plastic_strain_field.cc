// The plastic strain field of an elastic-plastic body: under a uniform
// strain every point returns to the same state as J2ReturnMapping alone,
// and the field's force, plastic work and energy are that state's values
// times the body's volume (plane strain, the sphere's meridian with its
// hoop strain, plane stress with its own eps_zz, the quarter sphere in 3D);
// the tangent it adds to K is the derivative of K u - f_p.

#include "body/geometry.h"
#include "body/solid_geometry.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/plastic_strain_field.h"
#include "half_disk.h"
#include "interpolated_field.h"
#include "material/j2_return_mapping.h"
#include "material/material.h"
#include "material/plane_stress_return_mapping.h"

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

using namespace DiskImpact;

namespace
{
  /// u = (a (x - c_x), b y[, b z]): uniform strains a, b (and hoop strain
  /// b on an axisymmetric body), zero normal displacement on the planes of
  /// symmetry y = 0 (and z = 0).
  template <int dim>
  class StretchField : public dealii::Function<dim>
  {
  public:
    StretchField(const double a, const double b, const double c_x)
        : dealii::Function<dim>(dim)
        , a(a)
        , b(b)
        , c_x(c_x)
    {
    }
    double
    value(const dealii::Point<dim> &x,
          const unsigned int        component) const override
    {
      return component == 0 ? a * (x[0] - c_x) : b * x[component];
    }

  private:
    double a, b, c_x;
  };

  /// The sphere: its meridian (Dimension 2) or the quarter in 3D.
  BodyGeometry
  sphere(const unsigned int dimension = 2)
  {
    dealii::ParameterHandler prm;
    BodyGeometry::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Body", "sphere");
    prm.set("Global refinements", dimension == 2 ? "1" : "0");
    if (dimension == 3)
      {
        prm.set("Dimension", "3");
        prm.set("Domain", "quarter sphere");
      }
    prm.leave_subsection();
    BodyGeometry geometry;
    geometry.parse_parameters(prm);
    return geometry;
  }

  /// The mesh of @p geometry, Q2, assembled with @p material (a Newton
  /// tangent too).
  template <int dim>
  struct Body
  {
    Body(const BodyGeometry &geometry, const Material &material)
        : triangulation(MPI_COMM_WORLD)
        , op(2)
    {
      if constexpr (dim == 2)
        geometry.create_triangulation(triangulation);
      else
        create_solid_triangulation(geometry, triangulation);
      op.setup(triangulation, geometry, true);
      op.assemble(material);
    }

    dealii::PETScWrappers::MPI::Vector
    interpolate(const dealii::Function<dim> &f) const
    {
      return interpolated_field(op, f);
    }

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    ElasticityOperator<dim>                           op;
  };

  /// A smooth field that strains the body unevenly.
  template <int dim>
  class WavyField : public dealii::Function<dim>
  {
  public:
    WavyField()
        : dealii::Function<dim>(dim)
    {
    }
    double
    value(const dealii::Point<dim> &x,
          const unsigned int        component) const override
    {
      return component == 0 ? std::sin(2. * x[0] + x[1] * x[1]) :
                              x[component] * std::cos(3. * x[0] - x[1]);
    }
  };

  /// At the uniform strain (a, b) beyond yield plus a wavy part, the
  /// tangent applied to a direction v against the central difference of
  /// K u - f_p(u) along v.
  template <int dim>
  void
  check_tangent(const BodyGeometry &geometry, Material material)
  {
    const double Y = 2e-3, H = 0.1, a = -6e-3, b = 1e-3, h = 1e-8;
    material.set_plasticity(Y, H);
    Body<dim>               body(geometry, material);
    const auto             &op = body.op;
    PlasticStrainField<dim> field(op, {material});
    auto u = body.interpolate(StretchField<dim>(a, b, geometry.center()[0]));
    const auto v = body.interpolate(WavyField<dim>());
    u.add(1e-3, v);

    auto internal_force = [&](const double s) {
      auto w = u, f_p = op.create_vector(), g = op.create_vector();
      w.add(s, v);
      field.evaluate(w, f_p);
      op.stiffness_matrix().vmult(g, w);
      g -= f_p;
      op.get_constraints().set_zero(g);
      return g;
    };
    auto difference = internal_force(h);
    difference -= internal_force(-h);
    difference /= 2. * h;

    auto  force = op.create_vector(), applied = op.create_vector();
    auto &tangent = body.op.tangent_reset_to_stiffness();
    field.evaluate(u, force, true, &tangent);
    REQUIRE(field.n_yielding_points() > 0);
    tangent.vmult(applied, v);
    op.get_constraints().set_zero(applied);

    // Without the plastic part the tangent is off by far more.
    auto elastic = op.create_vector();
    op.stiffness_matrix().vmult(elastic, v);
    op.get_constraints().set_zero(elastic);
    elastic -= difference;
    CHECK(elastic.l2_norm() > 1e-2 * difference.l2_norm());

    applied -= difference;
    CHECK(applied.l2_norm() <= 1e-6 * difference.l2_norm());
  }

  /// Two loading steps of the field u = s (a, b) at s = 1 and 2 against
  /// the return mapping at one point.
  template <int dim>
  void
  check_uniform_strain(const BodyGeometry &geometry,
                       Material            material,
                       const double        hoop_factor)
  {
    const double Y = 2e-3, H = 0.1, a = -6e-3, b = 1e-3;
    material.set_plasticity(Y, H);
    Body<dim>    body(geometry, material);
    const auto  &op     = body.op;
    const double volume = op.volume();

    PlasticStrainField<dim> field(op, {material});
    // The point's law: plane stress finds its own eps_zz.
    const std::unique_ptr<J2ReturnMapping> law =
      dim == 2 && material.plane_model() == PlaneModel::plane_stress ?
        std::make_unique<PlaneStressReturnMapping>(material.lame_lambda_3d(),
                                                   material.shear_modulus_3d(),
                                                   Y,
                                                   H) :
        std::make_unique<J2ReturnMapping>(material.lame_lambda_3d(),
                                          material.shear_modulus_3d(),
                                          Y,
                                          H);
    const J2ReturnMapping        &point = *law;
    auto                   u = op.create_vector(), force = op.create_vector();
    J2ReturnMapping::State state;
    dealii::SymmetricTensor<2, 3> stress;
    for (const double s : {1., 2.})
      {
        u = body.interpolate(
          StretchField<dim>(s * a, s * b, geometry.center()[0]));
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

namespace
{
  /// E = rho = 1, nu = 0.3.
  Material
  steel_like(const PlaneModel model)
  {
    Material material;
    material.set(model, 1., 0.3, 1.);
    return material;
  }
} // namespace

TEST_CASE("plastic strain field: the half disk in plane strain",
          "[plasticity][fe]")
{
  check_uniform_strain<2>(half_disk(1),
                          steel_like(PlaneModel::plane_strain),
                          0.);
  check_tangent<2>(half_disk(1), steel_like(PlaneModel::plane_strain));
}

TEST_CASE("plastic strain field: the axisymmetric sphere", "[plasticity][fe]")
{
  check_uniform_strain<2>(sphere(), steel_like(PlaneModel::axisymmetric), 1.);
  check_tangent<2>(sphere(), steel_like(PlaneModel::axisymmetric));
}

TEST_CASE("plastic strain field: the quarter sphere in 3D", "[plasticity][fe]")
{
  // A 3D body takes the 3D constants whatever its plane model.
  check_uniform_strain<3>(sphere(3), steel_like(PlaneModel::plane_strain), 1.);
  check_tangent<3>(sphere(3), steel_like(PlaneModel::plane_strain));
}

TEST_CASE("plastic strain field: the half disk in plane stress",
          "[plasticity][fe]")
{
  check_uniform_strain<2>(half_disk(1),
                          steel_like(PlaneModel::plane_stress),
                          0.);
  check_tangent<2>(half_disk(1), steel_like(PlaneModel::plane_stress));
}
