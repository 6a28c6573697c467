#include "material/j2_return_mapping.h"
#include "stress_tangent_check.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;
using dealii::SymmetricTensor;
using namespace point_constants;

namespace
{

  /// The strain of simple shear with engineering shear strain gamma.
  SymmetricTensor<2, 3>
  shear(const double gamma)
  {
    SymmetricTensor<2, 3> strain;
    strain[0][1] = 0.5 * gamma;
    return strain;
  }
} // namespace

TEST_CASE("J2 return mapping: simple shear against the closed form",
          "[plasticity]")
{
  // tau = mu (gamma - gamma_p) on the yield surface
  // sqrt(3) tau = Y + H gamma_p / sqrt(3) gives
  // gamma_p = (mu gamma - Y / sqrt(3)) / (mu + H / 3).
  for (const double H : {0., 0.05, 0.3})
    {
      const J2ReturnMapping  law(lambda, mu, Y, H);
      J2ReturnMapping::State state;
      const double           gamma_y = Y / (std::sqrt(3.) * mu);
      double                 work = 0., squares = 0., previous = 0.;
      const unsigned int     steps = 50;
      for (unsigned int k = 1; k <= steps; ++k)
        {
          const double gamma  = 4. * gamma_y * k / steps;
          const auto   result = law.update(shear(gamma), state);
          const double gamma_p =
            std::max(0., (mu * gamma - Y / std::sqrt(3.)) / (mu + H / 3.));
          CHECK(result.stress[0][1] ==
                Approx(mu * (gamma - gamma_p)).epsilon(1e-12));
          CHECK(result.state.equivalent_plastic_strain ==
                Approx(gamma_p / std::sqrt(3.)).margin(1e-15));
          CHECK(result.yielded == (gamma > gamma_y * (1. + 1e-12)));
          state = result.state;
          work += result.plastic_work;
          squares += (gamma_p - previous) * (gamma_p - previous);
          previous = gamma_p;
        }
      // The plastic work of the whole path, int tau d gamma_p with
      // tau = Y / sqrt(3) + H gamma_p / 3: backward Euler takes tau at each
      // step's end, which adds H dgamma_p^2 / 6 per step.
      const double gamma_p = state.equivalent_plastic_strain * std::sqrt(3.);
      const double exact =
        Y * gamma_p / std::sqrt(3.) + H * gamma_p * gamma_p / 6.;
      CHECK(work == Approx(exact + H * squares / 6.).epsilon(1e-12));
    }
}

TEST_CASE("J2 return mapping: the stress stays on the yield surface and a "
          "pressure never yields",
          "[plasticity]")
{
  const J2ReturnMapping  law(lambda, mu, Y, 0.1);
  J2ReturnMapping::State state;
  SymmetricTensor<2, 3>  strain;
  strain[0][0] = 0.02, strain[1][1] = -0.004, strain[2][2] = 0.001;
  strain[0][2] = 0.003, strain[1][2] = -0.002;
  const auto result = law.update(strain, state);
  REQUIRE(result.yielded);
  CHECK(
    std::sqrt(1.5) * deviator(result.stress).norm() ==
    Approx(Y + 0.1 * result.state.equivalent_plastic_strain).epsilon(1e-12));
  CHECK(std::abs(trace(result.state.plastic_strain)) <= 1e-15);
  // The mean stress is elastic: 3K tr(eps) / 3.
  CHECK(trace(result.stress) / 3. ==
        Approx((lambda + 2. / 3. * mu) * trace(strain)).epsilon(1e-12));
  const auto pressed =
    law.update(-0.5 * dealii::unit_symmetric_tensor<3>(), state);
  CHECK_FALSE(pressed.yielded);
}

TEST_CASE("J2 return mapping: the consistent tangent is d sigma / d eps",
          "[plasticity]")
{
  for (const double H : {0., 0.2})
    {
      const J2ReturnMapping  law(lambda, mu, Y, H);
      const J2ReturnMapping::State old = plastic_history();
      SymmetricTensor<2, 3> strain;
      strain[0][0] = 0.012, strain[1][1] = -0.003, strain[2][2] = 0.002;
      strain[0][1] = 0.004, strain[1][2] = -0.001;
      check_tangent_by_differences(law, strain, old, 3);
    }
}
