// The elasticity operator and its constitutive laws in three dimensions:
// the same code as the disk's and the sphere's, instantiated for dim = 3,
// checked on the unit cube against exact fields (Q2 elements hold every
// linear field exactly).

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "material/constitutive_law.h"
#include "material/material.h"

#include <deal.II/base/function.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace DiskImpact;

namespace
{
  constexpr int dim = 3;

  /// A linear displacement field u(x) = b + A x.
  class LinearField : public dealii::Function<dim>
  {
  public:
    LinearField(const dealii::Tensor<1, dim> &b,
                const dealii::Tensor<2, dim> &A)
        : dealii::Function<dim>(dim)
        , b(b)
        , A(A)
    {
    }

    double
    value(const dealii::Point<dim> &x, const unsigned int c) const override
    {
      return (b + A * x)[c];
    }

  private:
    dealii::Tensor<1, dim> b;
    dealii::Tensor<2, dim> A;
  };

  /// The unit cube, refined once, with Q2 elements, assembled for
  /// @p material.
  struct CubeOperator
  {
    explicit CubeOperator(const Material &material)
        : triangulation(MPI_COMM_WORLD)
        , op(2)
    {
      dealii::GridGenerator::hyper_cube(triangulation);
      triangulation.refine_global(1);
      op.setup(triangulation, BodyGeometry(), false);
      op.assemble(material);
    }

    /// The field @p field interpolated, constraints applied.
    dealii::PETScWrappers::MPI::Vector
    interpolate(const LinearField &field) const
    {
      auto u = op.create_vector();
      dealii::VectorTools::interpolate(op.get_mapping(),
                                       op.get_dof_handler(),
                                       field,
                                       u);
      return u;
    }

    /// x^T A y.
    static double
    form(const dealii::PETScWrappers::MPI::SparseMatrix &A,
         const dealii::PETScWrappers::MPI::Vector       &x,
         const dealii::PETScWrappers::MPI::Vector       &y)
    {
      auto Ay = y;
      A.vmult(Ay, y);
      return x * Ay;
    }

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    ElasticityOperator<dim>                           op;
  };

  /// Young's modulus 2.5, Poisson's ratio 0.3, density 1.7; relaxation time
  /// @p tau. Given as plane stress, whose in-plane constants differ from
  /// the 3D ones: a solid must not use them.
  Material
  steel_like(const double tau = 0.)
  {
    Material material;
    material.set(PlaneModel::plane_stress, 2.5, 0.3, 1.7, tau);
    return material;
  }
} // namespace

TEST_CASE("3D: the mass of a translation is the body's mass", "[3d]")
{
  const CubeOperator     cube(steel_like());
  dealii::Tensor<1, dim> direction;
  direction[0] = 0.6;
  direction[2] = 0.8;
  const auto u = cube.interpolate(LinearField(direction, {}));
  // rho V |d|^2 with V = 1, |d| = 1.
  CHECK(CubeOperator::form(cube.op.mass_matrix(), u, u) ==
        Approx(1.7).epsilon(1e-13));
}

TEST_CASE("3D: the six rigid motions cost no strain energy", "[3d]")
{
  const CubeOperator cube(steel_like());
  const double       scale = cube.op.stiffness_matrix().frobenius_norm();
  for (unsigned int mode = 0; mode < 6; ++mode)
    {
      dealii::Tensor<1, dim> translation;
      dealii::Tensor<2, dim> rotation;
      if (mode < 3)
        translation[mode] = 1.;
      else
        {
          // u = omega x x: the skew matrix of the unit axis mode - 3.
          const unsigned int i = (mode - 3 + 1) % 3, j = (mode - 3 + 2) % 3;
          rotation[i][j] = -1.;
          rotation[j][i] = 1.;
        }
      const auto u  = cube.interpolate(LinearField(translation, rotation));
      auto       Ku = u;
      cube.op.stiffness_matrix().vmult(Ku, u);
      INFO("rigid mode " << mode);
      CHECK(Ku.l2_norm() <= 1e-12 * scale * u.l2_norm());
    }
}

TEST_CASE("3D: a uniform strain stores V eps : C : eps / 2 with Lame's "
          "constants of E and nu",
          "[3d]")
{
  const double       E = 2.5, nu = 0.3;
  const double       lambda   = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double       mu       = E / (2. * (1. + nu));
  const double       tau      = 0.05;
  const Material     material = steel_like(tau);
  const CubeOperator cube(material);

  dealii::Tensor<2, dim> strain;
  strain[0][0] = 1e-3;
  strain[1][1] = -4e-4;
  strain[2][2] = 2e-4;
  strain[0][1] = strain[1][0] = 3e-4;
  strain[1][2] = strain[2][1] = -5e-4;
  double trace = 0., contraction = 0.;
  for (unsigned int i = 0; i < dim; ++i)
    {
      trace += strain[i][i];
      for (unsigned int j = 0; j < dim; ++j)
        contraction += strain[i][j] * strain[i][j];
    }
  // eps : C : eps = lambda (tr eps)^2 + 2 mu eps : eps, over V = 1.
  const double expected = lambda * trace * trace + 2. * mu * contraction;
  const auto   u        = cube.interpolate(LinearField({}, strain));
  CHECK(CubeOperator::form(cube.op.stiffness_matrix(), u, u) ==
        Approx(expected).epsilon(1e-12));
  // Kelvin-Voigt with a relaxation time only: D = tau C.
  REQUIRE(cube.op.has_damping());
  CHECK(CubeOperator::form(cube.op.damping_matrix(), u, u) ==
        Approx(tau * expected).epsilon(1e-12));
  CHECK(dynamic_cast<const KelvinVoigtLaw<dim> *>(
          &cube.op.constitutive_law()) != nullptr);
}
