#include "reference/free_disk_mode_shapes.h"
#include "reference/free_disk_modes.h"
#include "reference/modal_expansion_impact.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

using namespace DiskImpact::Reference;

namespace
{
  FreeDiskModes
  unit_disk_modes(const double nu2)
  {
    return FreeDiskModes(nu2, 1. / std::sqrt(1. - nu2 * nu2), 1.);
  }

  /// int_disk u_a . u_b dA on the unit disk: trapezoidal rule in phi (exact
  /// for these trigonometric polynomials), adaptive Gauss-Kronrod in r.
  double
  mass_product(const FreeDiskModeShape &a, const FreeDiskModeShape &b)
  {
    const unsigned int na = a.label().n, nb = b.label().n;
    const unsigned int n_phi            = 4 * (na + nb) + 8;
    auto               radial_integrand = [&](const double r) {
      const auto   pa = a.profile(r), pb = b.profile(r);
      double       sum = 0.;
      const double h   = 2. * M_PI / n_phi;
      for (unsigned int i = 0; i < n_phi; ++i)
        {
          const double phi = i * h;
          sum +=
            h * (pa.u_r * std::cos(na * phi) * pb.u_r * std::cos(nb * phi) +
                 pa.u_phi * std::sin(na * phi) * pb.u_phi * std::sin(nb * phi));
        }
      return r * sum;
    };
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      radial_integrand, 0., 1., 15, 1e-13);
  }

  ModalImpactResult
  collide(const unsigned int    n_modes,
          const double          steps_per_period,
          const ModalIntegrator integrator = ModalIntegrator::strang_splitting)
  {
    ModalImpactConfig config;
    config.n_modes          = n_modes;
    config.velocity         = 0.1;
    config.alpha            = 100.;
    config.angular_points   = 128;
    config.steps_per_period = steps_per_period;
    config.integrator       = integrator;
    return ModalExpansionImpact(config).run();
  }
} // namespace

TEST_CASE("Mode shapes are traction free at r = R", "[modal expansion]")
{
  for (const double nu2 : {0.33, 0.9})
    {
      const auto modes = unit_disk_modes(nu2);
      for (const auto &[label, kappa] : lowest_symmetric_modes(modes, 40))
        {
          const FreeDiskModeShape shape(nu2, 1., label, kappa);
          const auto              traction = shape.boundary_tractions();
          // scale: the strain of the mode is of order kappa' |u|
          const double scale = kappa * std::sqrt(2. / (1. - nu2)) *
                               std::hypot(shape.edge_radial_amplitude(),
                                          shape.edge_tangential_amplitude());
          INFO("nu2 = " << nu2 << ", n = " << label.n << ", l = " << label.l);
          CHECK(std::abs(traction.first) <= 1e-12 * scale);
          CHECK(std::abs(traction.second) <= 1e-12 * scale);

          // the analytic derivatives against central differences
          const double r = 0.7, h = 1e-5;
          const auto   p = shape.profile(r), pp = shape.profile(r + h),
                     pm = shape.profile(r - h);
          CHECK(p.du_r_dr == Approx((pp.u_r - pm.u_r) / (2. * h))
                               .epsilon(1e-6)
                               .margin(1e-8 * scale));
          CHECK(p.du_phi_dr == Approx((pp.u_phi - pm.u_phi) / (2. * h))
                                 .epsilon(1e-6)
                                 .margin(1e-8 * scale));
        }
    }
}

TEST_CASE("Mode shapes have the mass of the disk (eq. 26)", "[modal expansion]")
{
  const double nu2   = 0.33;
  const auto   modes = unit_disk_modes(nu2);
  for (const auto &[label, kappa] : lowest_symmetric_modes(modes, 60))
    {
      const FreeDiskModeShape shape(nu2, 1., label, kappa);
      INFO("n = " << label.n << ", l = " << label.l);
      CHECK(mass_product(shape, shape) == Approx(M_PI).epsilon(1e-10));
    }
  // the radius scales the profiles: int |u|^2 dA = pi R^2 at R = 2 too
  const ModeLabel         quadrupole{2, 0, ModeFamily::mixed};
  const FreeDiskModeShape on_unit(nu2, 1., quadrupole, modes.kappa(quadrupole));
  const FreeDiskModeShape on_two(nu2, 2., quadrupole, modes.kappa(quadrupole));
  CHECK(on_two.radial_mass_integral() * on_two.angular_norm_factor() ==
        Approx(4. * M_PI).epsilon(1e-12));
  CHECK(on_two.edge_radial_amplitude() ==
        Approx(on_unit.edge_radial_amplitude()).epsilon(1e-12));
}

TEST_CASE("Modes of the same order are mass-orthogonal", "[modal expansion]")
{
  const double nu2   = 0.33;
  const auto   modes = unit_disk_modes(nu2);
  for (const unsigned int n : {0u, 1u, 2u, 5u})
    {
      const ModeFamily family = n == 0 ? ModeFamily::radial : ModeFamily::mixed;
      std::vector<FreeDiskModeShape> shapes;
      for (unsigned int l = 0; l < 4; ++l)
        shapes.emplace_back(nu2,
                            1.,
                            ModeLabel{n, l, family},
                            modes.kappa(ModeLabel{n, l, family}));
      for (unsigned int i = 0; i < shapes.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          {
            INFO("n = " << n << ", l = " << i << ", " << j);
            CHECK(std::abs(mass_product(shapes[i], shapes[j])) <= 1e-9);
          }
      // n = 1: no momentum, i.e. orthogonal to the rigid translation e_x
      // (u_r = cos phi, u_phi = -sin phi): int (u_r - u_phi) r dr = 0
      if (n == 1)
        for (const auto &shape : shapes)
          {
            const double momentum =
              boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                [&](const double r) {
                  const auto p = shape.profile(r);
                  return r * (p.u_r - p.u_phi);
                },
                0.,
                1.,
                15,
                1e-13);
            CHECK(std::abs(momentum) <= 1e-10);
          }
    }
}

TEST_CASE("The symmetric spectrum: high orders, no spurious roots",
          "[modal expansion]")
{
  // 400 modes reach orders n ~ 50, where the boundary determinant
  // underflows at small kappa: every root must be a sign change of the
  // frequency equation, the roots of each order ascend with l, and the
  // low part is the one a scan from kappa = 0 finds for n <= 8.
  const auto modes = unit_disk_modes(0.33);
  const auto found = lowest_symmetric_modes(modes, 400);
  REQUIRE(found.size() == 400);
  std::map<unsigned int, double> last;
  for (const auto &[label, kappa] : found)
    {
      CAPTURE(label.n, label.l, kappa);
      const double h = 1e-9 * kappa;
      CHECK(modes.frequency_equation(label.n, label.family, kappa - h) *
              modes.frequency_equation(label.n, label.family, kappa + h) <=
            0.);
      CHECK(kappa > last[label.n]);
      last[label.n] = kappa;
    }
  // Orders 1 ... 8 below kappa = 10: as many roots as sign changes of the
  // frequency equation on a fine grid from kappa = 1e-3 (no root is lost
  // below the scan's start kappa' = n / 2).
  for (unsigned int n = 1; n <= 8; ++n)
    {
      unsigned int sign_changes = 0;
      double previous = modes.frequency_equation(n, ModeFamily::mixed, 1e-3);
      for (double k = 1e-3 + 2e-3; k < 10.; k += 2e-3)
        {
          const double value =
            modes.frequency_equation(n, ModeFamily::mixed, k);
          sign_changes += previous * value < 0.;
          previous = value;
        }
      CAPTURE(n);
      CHECK(modes.kappa_roots(n, ModeFamily::mixed, 10.).size() ==
            sign_changes);
    }
}

TEST_CASE("Splitting integrator: energy error shrinks as dt^2",
          "[modal expansion]")
{
  const auto coarse = collide(10, 20.);
  const auto medium = collide(10, 40.);
  const auto fine   = collide(10, 80.);
  CHECK(fine.energy_error < 1e-4);
  CHECK(coarse.energy_error / medium.energy_error == Approx(4.).epsilon(0.1));
  CHECK(medium.energy_error / fine.energy_error == Approx(4.).epsilon(0.1));
  // the modes take what the translation loses: 1 - eps^2 = sum of E_k
  double vibration = 0.;
  for (const auto &mode : fine.modes)
    vibration += mode.energy_after;
  CHECK(vibration == Approx(1. - fine.epsilon * fine.epsilon).epsilon(1e-3));
  CHECK(fine.separated);
}

TEST_CASE("Interaction-picture RK4: fourth order, same epsilon",
          "[modal expansion]")
{
  const auto rk     = ModalIntegrator::runge_kutta_interaction_picture;
  const auto coarse = collide(10, 20., rk);
  const auto fine   = collide(10, 40., rk);
  CHECK(coarse.energy_error / fine.energy_error > 12.);
  CHECK(fine.energy_error < 1e-6);
  const auto split = collide(10, 80.);
  CHECK(split.epsilon == Approx(fine.epsilon).epsilon(1e-4));
}

TEST_CASE("A rigid disk (no modes) bounces back with eps = 1",
          "[modal expansion]")
{
  const auto rigid = collide(0, 20.);
  CHECK(rigid.separated);
  CHECK(rigid.epsilon == Approx(1.).epsilon(1e-7));
  CHECK(rigid.modes.empty());
  // rigid disk: U = (m v^2 / 2) sech^2(alpha v t / 2), force alpha U, so
  // the force exceeds 1 % of its peak for 4 arcsech(0.1) / (alpha v)
  const double arcsech = std::log((1. + std::sqrt(0.99)) / 0.1);
  CHECK(rigid.contact_time ==
        Approx(4. * arcsech / (100. * 0.1)).epsilon(2e-3));
  CHECK(rigid.max_force == Approx(100. * 0.5 * M_PI * 0.01).epsilon(1e-3));
}

TEST_CASE("Vibrations take energy; more modes soften the collision",
          "[modal expansion]")
{
  const double rigid = collide(0, 20.).epsilon;
  const double one   = collide(1, 20.).epsilon;
  const double five  = collide(5, 20.).epsilon;
  const double forty = collide(40, 20.).epsilon;
  CHECK(one < rigid - 0.1);
  CHECK(five < rigid - 0.02);
  CHECK(forty < rigid - 0.02);
  // Gerl & Zippelius 1999, section 4: eps rises towards 1 with the number of
  // modes
  CHECK(one < five);
  CHECK(five < forty);
}

TEST_CASE("A wall force below the contact threshold leaves no contact window",
          "[modal expansion]")
{
  // The threshold is 1 % of the rigid disk's peak force alpha m v^2 / 2R.
  // A stiff wall and a fast impact keep the elastic disk's force below it:
  // the collision happens, but it has no contact time and no averages.
  ModalImpactConfig config;
  config.in_plane_poisson_ratio = 0.9;
  config.n_modes                = 800;
  config.velocity               = 0.5;
  config.alpha                  = 1000.;
  const auto result             = ModalExpansionImpact(config).run();
  CHECK(result.separated);
  CHECK(result.epsilon > 0.5);
  CHECK(result.epsilon < 1.);
  CHECK(result.max_force < 0.01 * config.alpha * 0.5 * M_PI * 0.25);
  CHECK(std::isnan(result.contact_time));
  const auto count = [&](auto &&predicate) {
    return std::count_if(result.modes.begin(), result.modes.end(), predicate);
  };
  CHECK(result.modes.size() == 800);
  CHECK(count([](const auto &m) { return std::isnan(m.average_energy); }) ==
        800);
  CHECK(count([](const auto &m) { return std::isfinite(m.energy_after); }) ==
        800);
}
