#include "reference/collision_ode.h"
#include "reference/dem_contact_models.h"
#include "reference/hertz_impact.h"
#include "reference/linear_dashpot.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

using namespace DiskImpact::Reference;

TEST_CASE("LIGGGHTS' Hertz restitution: its epsilon and the input for it",
          "[dem]")
{
  // Tsuji's sqrt(5/6) makes the Hertz model's epsilon nearly its input
  // (the LIGGGHTS run of bench/dem_check.py measures 0.9000017 at 2000
  // steps per contact, 0.9000003 at 4000).
  CHECK(liggghts_hertz_epsilon(0.9) == Approx(0.9).margin(1e-6));
  CHECK(liggghts_hertz_epsilon(1.) == 1.);
  for (const double eps : {0.3, 0.7, 0.95, 0.999})
    CHECK(liggghts_hertz_epsilon(liggghts_hertz_input(eps)) ==
          Approx(eps).margin(1e-12));
  CHECK_THROWS(liggghts_hertz_input(1.5));
}

TEST_CASE("LAMMPS' viscoelastic damping is Ramírez et al.'s A dF/dt", "[dem]")
{
  // A sphere on a wall, not unit-valued: E*, R, m, A, v.
  const double   e_star = 7.3, radius = 0.4, mass = 2.1, A = 0.03, v = 0.2;
  const ForceLaw hertz{[&](const double d) {
                         return d > 0. ?
                                  hertz_sphere_stiffness(e_star, radius) *
                                    std::pow(d, 1.5) :
                                  0.;
                       },
                       [&](const double d) {
                         return d > 0. ?
                                  1.5 * hertz_sphere_stiffness(e_star, radius) *
                                    std::sqrt(d) :
                                  0.;
                       }};
  const double   eta = lammps_viscoelastic_damping(A, e_star, mass);
  // LAMMPS: eta_n0 a m_eff d' with a = sqrt(R_eff d).
  const auto lammps = [&](const double d, const double d_dot) {
    return d > 0. ? eta * std::sqrt(radius * d) * mass * d_dot : 0.;
  };
  const auto paper_ode = collide(mass, v, hertz, A, EndCriterion::force);
  const auto dem       = collide(mass, v, hertz, lammps, EndCriterion::force);
  CHECK(dem.epsilon == Approx(paper_ode.epsilon).epsilon(1e-10));
  CHECK(dem.contact_time == Approx(paper_ode.contact_time).epsilon(1e-10));
  CHECK(paper_ode.epsilon < 0.99);
}

TEST_CASE("Yade's ViscElMat: the force-clipped linear spring-dashpot", "[dem]")
{
  // ViscElMat's k and c from (en, tc), integrated with a damping force cut
  // so that the total force is never attractive, to the overlap's zero.
  const double mass = 1.7, v = 0.3;
  for (const double en : {0.2, 0.7, 0.9714911595, 0.9999})
    {
      const double   tc     = 2.3e-3;
      const double   log_en = std::log(en);
      const double   k = mass * (M_PI * M_PI + log_en * log_en) / (tc * tc);
      const double   c = -2. * mass * log_en / tc;
      const ForceLaw linear{[&](const double d) { return k * d; },
                            [&](const double) { return k; }};
      const auto     clipped = [&](const double d, const double d_dot) {
        return std::max(c * d_dot, -k * d);
      };
      const auto unclipped = [&](const double, const double d_dot) {
        return c * d_dot;
      };
      const auto yade =
        collide(mass, v, linear, clipped, EndCriterion::overlap, 1e-14);
      const auto classical =
        collide(mass, v, linear, unclipped, EndCriterion::overlap, 1e-14);
      CHECK(classical.epsilon == Approx(en).epsilon(1e-10));
      CHECK(classical.contact_time == Approx(tc).epsilon(1e-10));

      const auto model = yade_viscel_collision(en, tc);
      CHECK(model.epsilon == Approx(yade.epsilon).epsilon(1e-10));
      CHECK(model.contact_time == Approx(yade.contact_time).epsilon(1e-9));
      CHECK(model.epsilon > en);

      const auto inputs = yade_viscel_inputs(model.epsilon, model.contact_time);
      CHECK(inputs.epsilon == Approx(en).epsilon(1e-12));
      CHECK(inputs.contact_time == Approx(tc).epsilon(1e-12));
    }
  CHECK_THROWS(yade_viscel_inputs(0., 1.));
}

TEST_CASE("The linear spring-dashpot for a given epsilon and contact time",
          "[dem]")
{
  // Schwager & Pöschel's dashpot, ended at zero overlap, with
  // beta = eta / 2m and omega0^2 = k / m, must give the inputs back.
  for (const double epsilon : {0.5, 0.9, 0.9789, 1.})
    {
      const double mass = 0.0123, contact_time = 1.5e-6;
      const auto   law    = linear_spring_dashpot(epsilon, contact_time, mass);
      const double beta   = law.damping / (2. * mass);
      const double omega0 = std::sqrt(law.stiffness / mass);
      CHECK(dashpot_restitution_overlap_criterion(beta, omega0) ==
            Approx(epsilon).epsilon(1e-13));
      CHECK(M_PI / std::sqrt(omega0 * omega0 - beta * beta) ==
            Approx(contact_time).epsilon(1e-13));
    }
  CHECK_THROWS(linear_spring_dashpot(0., 1e-6, 1.));
  CHECK_THROWS(linear_spring_dashpot(0.9, -1e-6, 1.));
}

namespace
{
  /// epsilon of LIGGGHTS' thornton_ning at v / v_y = @p u, by velocity
  /// Verlet with steps of 1e-5 on its force law in units of d_y, F_y and
  /// the mass (so that v_y^2 = 4/5): Hertz and the plastic line while the
  /// overlap grows, then Hertz's stiffness of the current overlap until the
  /// force is 0.
  double
  integrated_thornton_ning(const double u)
  {
    const double v0 = u * std::sqrt(0.8);
    double       x = 0., v = v0, x_m = 0., f_m = 0.;
    bool         unloading = false;
    const auto   force     = [&](const double y) {
      if (unloading)
        return f_m - (x_m * std::sqrt(x_m) - y * std::sqrt(y));
      return y <= 1. ? y * std::sqrt(y) : 1. + 1.5 * (y - 1.);
    };
    const double dt = 1e-5;
    double       a  = -force(x);
    while (true)
      {
        const double x_new = x + v * dt + 0.5 * a * dt * dt;
        if (!unloading && x_new < x)
          {
            f_m       = force(x);
            x_m       = x;
            unloading = true;
          }
        if (unloading && force(x_new) <= 0.)
          return -v / v0;
        const double a_new = -force(x_new);
        v += 0.5 * (a + a_new) * dt;
        x = x_new, a = a_new;
      }
  }
} // namespace

TEST_CASE("LIGGGHTS' thornton_ning: epsilon of its force law", "[dem]")
{
  CHECK(thornton_ning_epsilon(0.5) == 1.);
  CHECK(thornton_ning_epsilon(1. + 1e-9) == Approx(1.).margin(1e-8));
  double previous = 1.;
  for (const double u : {1.5, 3., 10., 30., 100.})
    {
      const double eps = thornton_ning_epsilon(u);
      CHECK(eps == Approx(integrated_thornton_ning(u)).margin(2e-6));
      CHECK(eps < previous);
      previous = eps;
    }
  // Johnson's fully plastic scaling eps ~ u^{-1/4} at u >> 1.
  const double slope =
    std::log(thornton_ning_epsilon(1e6) / thornton_ning_epsilon(1e5)) /
    std::log(10.);
  CHECK(slope == Approx(-0.25).margin(2e-3));
  CHECK_THROWS(thornton_ning_epsilon(0.));
}

namespace
{
  /// epsilon and contact time of Yade's LudingMat (kc = 0, G0 = 0) at
  /// v / v_p = @p x with kp / k1 = 1 + @p a, by velocity Verlet with steps
  /// of 1e-5 on its force law in units of k1, the mass and d_p (so that
  /// v_p = 1): k1 d while the overlap grows below d_p, kp (d - d_p0) beyond;
  /// once it shrinks, k2 (d - d0) with k2 and d0 of the largest overlap,
  /// until the force is 0.
  std::pair<double, double>
  integrated_luding(const double x, const double a)
  {
    const double kp = 1. + a, d_p0 = 1. - 1. / kp;
    double       d = 0., v = x, t = 0., d_max = 0., k2 = 1., d0 = 0.;
    bool         unloading = false;
    const auto   force     = [&](const double y) {
      if (unloading)
        return k2 * (y - d0);
      return y <= 1. ? y : kp * (y - d_p0);
    };
    const double dt           = 1e-5;
    double       acceleration = -force(d);
    while (true)
      {
        const double d_new = d + v * dt + 0.5 * acceleration * dt * dt;
        if (!unloading && d_new < d)
          {
            d_max     = d;
            k2        = 1. + a * std::min(d_max, 1.);
            d0        = d_max <= 1. ? (1. - 1. / k2) * d_max : d_p0;
            unloading = true;
          }
        t += dt;
        if (unloading && force(d_new) <= 0.)
          return {-v / x, t};
        const double a_new = -force(d_new);
        v += 0.5 * (acceleration + a_new) * dt;
        d = d_new, acceleration = a_new;
      }
  }
} // namespace

TEST_CASE("Yade's LudingMat: epsilon and contact time of its force law",
          "[dem]")
{
  for (const double a : {0.5, 3.})
    for (const double x : {0.2, 0.9, 1.5, 4.})
      {
        const auto [epsilon, time] = integrated_luding(x, a);
        CHECK(luding_epsilon(x, a) == Approx(epsilon).margin(1e-4));
        CHECK(luding_contact_time(x, a) == Approx(time).margin(1e-4));
      }
  // continuous at v_p, back toward 1 far beyond it
  CHECK(luding_epsilon(1. + 1e-12, 3.) == Approx(0.5).epsilon(1e-9));
  CHECK(luding_epsilon(1e3, 3.) == Approx(1.).margin(1e-6));
  CHECK_THROWS(luding_epsilon(0., 3.));
  CHECK_THROWS(luding_contact_time(1., 0.));
}
