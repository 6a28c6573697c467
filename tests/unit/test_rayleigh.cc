#include "reference/collision_ode.h"
#include "reference/free_disk_mode_shapes.h"
#include "reference/rayleigh_vibration.h"

#include <boost/numeric/odeint.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace DiskImpact::Reference;

namespace
{
  const double nu2 = 0.33;
  // C_com, docs/theory/disk-contact-constants.md
  const double constant = -1. - 2. / M_PI - nu2 / 4.;

  /// Energy of one mode after the 1-DOF collision, by integrating
  /// delta, Q together in time (Dormand-Prince), without Fourier integrals.
  double
  mode_energy_by_time_integration(const double             v,
                                  const FreeDiskModeShape &shape)
  {
    using State        = std::array<double, 4>; // delta, delta', Q, Q'
    const double   m   = M_PI;
    const double   w   = shape.kappa() / std::sqrt(1. - nu2 * nu2);
    const double   C   = shape.edge_radial_amplitude();
    const ForceLaw law = disk_force_law(1., 1., constant);
    const double t_c = collide(m, v, law, 0., EndCriterion::force).contact_time;
    State        y{{0., v, 0., 0.}};
    boost::numeric::odeint::integrate_adaptive(
      boost::numeric::odeint::make_controlled(
        1e-13, 1e-13, boost::numeric::odeint::runge_kutta_dopri5<State>()),
      [&](const State &x, State &dxdt, double) {
        const double P = law.force(x[0]);
        dxdt           = {{x[1], -P / m, x[3], -w * w * x[2] - C * P / m}};
      },
      y,
      0.,
      t_c,
      1e-6);
    return 0.5 * m * (y[3] * y[3] + w * w * y[2] * y[2]);
  }
} // namespace

TEST_CASE("Rayleigh: mode energies equal a direct time integration",
          "[rayleigh]")
{
  const double v      = 1e-3;
  const auto   shapes = symmetric_mode_shapes(nu2, 6);
  const auto   result = rayleigh_vibration(v, constant, nu2, shapes);
  const double E0     = 0.5 * M_PI * v * v;
  REQUIRE(result.modes.size() == 6);
  double sum = 0.;
  for (unsigned int k = 0; k < shapes.size(); ++k)
    {
      const double direct = mode_energy_by_time_integration(v, shapes[k]) / E0;
      INFO("mode " << k << ": " << result.modes[k].energy_fraction << " vs "
                   << direct);
      CHECK(result.modes[k].energy_fraction ==
            Approx(direct).epsilon(1e-6).margin(1e-12));
      sum += result.modes[k].energy_fraction;
    }
  CHECK(result.vibration_fraction == Approx(sum).epsilon(1e-14));
  CHECK(result.epsilon() == Approx(std::sqrt(1. - sum)).epsilon(1e-14));
}

TEST_CASE("Rayleigh with feedback: energy is conserved, the force stays "
          "compressive, the centre's approach follows the 1-DOF law closely",
          "[rayleigh]")
{
  const double v      = 1e-3;
  const auto   shapes = symmetric_mode_shapes(nu2, 25);
  const auto   impact = rayleigh_impact(v, constant, nu2, shapes);
  const auto   one_dof =
    collide(M_PI, v, disk_force_law(1., 1., constant), 0., EndCriterion::force);
  INFO("epsilon " << impact.epsilon << ", vibration "
                  << impact.vibration_fraction << ", energy error "
                  << impact.energy_error);
  // RK4 at 40 steps per shortest period: drift far below the vibration.
  CHECK(impact.energy_error < 1e-6);
  // Energy balance after the collision: translation + vibration = initial.
  CHECK(impact.epsilon * impact.epsilon + impact.vibration_fraction ==
        Approx(1.).margin(1e-6));
  CHECK(impact.epsilon < 1.);
  // The vibration shifts the compression by a few per mille at most: the
  // largest approach is the 1-DOF one to 1 %, the contact time to 5 %.
  CHECK(impact.max_compression == Approx(one_dof.max_overlap).epsilon(1e-2));
  CHECK(impact.contact_time == Approx(one_dof.contact_time).epsilon(5e-2));
}

TEST_CASE("Rayleigh with feedback: too many modes for the contact width",
          "[rayleigh]")
{
  // At v = 0.02 c the Hertz half-width is about 0.2 R; 25 modes resolve
  // wavelengths below it and their point-force compliance exceeds the law's.
  const auto shapes = symmetric_mode_shapes(nu2, 25);
  CHECK_THROWS_AS(rayleigh_impact(0.02, constant, nu2, shapes), TooManyModes);
  CHECK_NOTHROW(rayleigh_impact(
    0.02,
    constant,
    nu2,
    std::vector<FreeDiskModeShape>(shapes.begin(), shapes.begin() + 5)));
}
