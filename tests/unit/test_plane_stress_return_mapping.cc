// Von Mises plasticity under plane stress: the equibiaxial stretch against
// its closed form (sigma_xx = sigma_yy, sigma_zz = 0: the von Mises stress
// is sigma_xx itself), sigma_zz = 0 and the condensed tangent against
// central differences of the in-plane stress.

#include "material/plane_stress_return_mapping.h"
#include "stress_tangent_check.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;
using dealii::SymmetricTensor;
using namespace point_constants;

TEST_CASE("plane stress return mapping: the equibiaxial stretch against the "
          "closed form",
          "[plasticity]")
{
  // sigma_xx = sigma_yy = s, flow along dev sigma = s (1, 1, -2) / 3:
  // eps_p = alpha (1/2, 1/2, -1), s = E / (1 - nu) (e - alpha / 2) on the
  // yield surface s = Y + H alpha, so
  // alpha = (E e / (1 - nu) - Y) / (H + E / (2 (1 - nu))).
  for (const double H : {0., 0.05})
    {
      const PlaneStressReturnMapping law(lambda, mu, Y, H);
      J2ReturnMapping::State         state;
      const double                   biaxial = E / (1. - nu);
      const double                   e_y     = Y / biaxial;
      for (unsigned int k = 1; k <= 20; ++k)
        {
          const double          e = 3. * e_y * k / 20.;
          SymmetricTensor<2, 3> strain;
          strain[0][0] = strain[1][1] = e;
          const auto   result         = law.update(strain, state);
          const double alpha =
            std::max(0., (biaxial * e - Y) / (H + 0.5 * biaxial));
          const double s = biaxial * (e - 0.5 * alpha);
          CHECK(result.stress[0][0] == Approx(s).epsilon(1e-12));
          CHECK(result.stress[1][1] == Approx(s).epsilon(1e-12));
          CHECK(std::abs(result.stress[2][2]) <= 1e-14 * Y);
          CHECK(result.state.equivalent_plastic_strain ==
                Approx(alpha).margin(1e-15));
          CHECK(result.state.plastic_strain[2][2] ==
                Approx(-alpha).margin(1e-15));
          CHECK(result.yielded == (e > e_y * (1. + 1e-12)));
          // The elastic stress of the elastic strain is the stress.
          const SymmetricTensor<2, 3> elastic =
            law.elastic_stress(strain - result.state.plastic_strain);
          CHECK((elastic - result.stress).norm() <= 1e-12 * Y);
          state = result.state;
        }
    }
}

TEST_CASE("plane stress return mapping: the condensed tangent is d sigma / d "
          "eps in the plane",
          "[plasticity]")
{
  for (const double H : {0., 0.2})
    {
      const PlaneStressReturnMapping law(lambda, mu, Y, H);
      const J2ReturnMapping::State   old = plastic_history();
      SymmetricTensor<2, 3>          strain;
      strain[0][0] = 0.012, strain[1][1] = -0.003, strain[0][1] = 0.004;
      CHECK(std::abs(law.update(strain, old).stress[2][2]) <= 1e-14 * Y);
      check_tangent_by_differences(law, strain, old, 2);
      // Where it stays elastic, the plane-stress stiffness.
      const auto elastic = law.update(1e-2 * strain, J2ReturnMapping::State());
      REQUIRE_FALSE(elastic.yielded);
      SymmetricTensor<2, 3> plane = 1e-2 * strain;
      CHECK((elastic.stress - law.elastic_tangent() * plane).norm() <=
            1e-14 * Y);
      CHECK(elastic.stress[0][0] ==
            Approx(E / (1. - nu * nu) * (plane[0][0] + nu * plane[1][1]))
              .epsilon(1e-12));
    }
}
