#include "reference/hertz_impact.h"
#include "reference/log_contact_law.h"
#include "reference/one_dof_impact.h"
#include "reference/sphere_finite_size.h"
#include "reference/two_body_contact.h"
#include "reference/wall_contact_theory.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace DiskImpact::Reference;

namespace
{
  /// A body in units that are deliberately not 1.
  constexpr double E = 2.5, R = 0.7, density = 1.3;

  /// The disk's C_com in plane strain with nu = 0.3 (nu2 = 3/7).
  double
  disk_constant()
  {
    return centre_of_mass_constant(3. / 7.);
  }

  /// The sphere's D0 for the centre of mass at nu = 0.3
  /// (docs/theory/sphere-finite-size.md).
  const double sphere_constant =
    sphere_finite_size_constants(0.3).centre_of_mass;

  /// The wall law of one body, to compare with.
  ForceLaw
  wall_law(const bool sphere, const ContactBody &b)
  {
    return sphere ? sphere_force_law(b.modulus, b.radius, b.constant) :
                    disk_force_law(b.modulus, b.radius, b.constant);
  }

  double
  approach(const bool         sphere,
           const double       force,
           const ContactBody &b1,
           const ContactBody &b2)
  {
    return sphere ? two_sphere_approach(force, b1, b2) :
                    two_disk_approach(force, b1, b2);
  }

  /// The force unit pi E R (disk, per thickness) or pi E R^2 (sphere).
  double
  force_unit(const bool sphere, const ContactBody &b)
  {
    return M_PI * b.modulus * b.radius * (sphere ? b.radius : 1.);
  }

  /// Dissimilar pairs: radius ratios 1, 1/2, 1/4, moduli ratios 1, 3, 1/3.
  std::vector<std::pair<ContactBody, ContactBody>>
  dissimilar_pairs(const bool sphere)
  {
    std::vector<std::pair<ContactBody, ContactBody>> pairs;
    const double c1 = sphere ? sphere_constant : disk_constant();
    const double c2 = sphere ?
                        sphere_finite_size_constants(0.45).centre_of_mass :
                        centre_of_mass_constant(0.25);
    for (const double radius_ratio : {1., 0.5, 0.25})
      for (const double modulus_ratio : {1., 3., 1. / 3.})
        pairs.push_back(
          {{R, E, c1}, {radius_ratio * R, modulus_ratio * E, c2}});
    return pairs;
  }
} // namespace

TEST_CASE("Two bodies: identical disks approach twice the wall law",
          "[reference][two body]")
{
  const ContactBody   b{R, E, disk_constant()};
  const LogContactLaw log_law(b.constant);
  const ForceLaw      wall = disk_force_law(E, R, b.constant);
  const ForceLaw      pair = two_body_force_law(false, b, b);
  const double        unit = M_PI * E * R;
  for (const double x : {1e-8, 1e-5, 1e-3, 1e-2, 0.1})
    {
      CAPTURE(x);
      CHECK(two_disk_approach(unit * x, b, b) ==
            Approx(2. * R * log_law.compression(x)).epsilon(1e-12));
      CHECK(two_body_half_width(false, unit * x, b, b) ==
            Approx(R * hertz_half_width(x)).epsilon(1e-12));
    }
  for (const double d : {1e-6, 1e-4, 1e-3, 1e-2, 0.05, 0.2})
    {
      const double delta = d * R;
      CAPTURE(d);
      CHECK(pair.force(2. * delta) == Approx(wall.force(delta)).epsilon(1e-10));
      CHECK(pair.derivative(2. * delta) ==
            Approx(0.5 * wall.derivative(delta)).epsilon(1e-10));
    }
  CHECK(two_body_largest_approach(false, b, b) ==
        Approx(2. * R * log_law.maximum_compression()).epsilon(1e-12));
  CHECK(pair.force(0.) == 0.);
  CHECK(pair.force(-1e-3) == 0.);
  CHECK(pair.derivative(-1e-3) == 0.);
}

TEST_CASE("Two bodies: identical spheres approach twice the wall law",
          "[reference][two body]")
{
  for (const double D : {0., sphere_constant, 0.3})
    {
      CAPTURE(D);
      const ContactBody b{R, E, D};
      const ForceLaw    wall = sphere_force_law(E, R, D);
      const ForceLaw    pair = two_body_force_law(true, b, b);
      const double      unit = M_PI * E * R * R;
      for (const double x : {1e-8, 1e-5, 1e-3, 1e-2})
        {
          CAPTURE(x);
          CHECK(two_sphere_approach(unit * x, b, b) ==
                Approx(2. * R * (hertz_sphere_approach(x) + M_PI * D * x))
                  .epsilon(1e-12));
          CHECK(two_body_half_width(true, unit * x, b, b) ==
                Approx(R * std::cbrt(0.75 * M_PI * x)).epsilon(1e-12));
        }
      for (const double d : {1e-6, 1e-4, 1e-3, 1e-2, 0.05})
        {
          const double delta = d * R;
          CAPTURE(d);
          CHECK(pair.force(2. * delta) ==
                Approx(wall.force(delta)).epsilon(1e-10));
          CHECK(pair.derivative(2. * delta) ==
                Approx(0.5 * wall.derivative(delta)).epsilon(1e-10));
        }
    }
}

TEST_CASE("Two bodies: the force law inverts the sum of the two bodies' "
          "approaches",
          "[reference][two body]")
{
  // equivalent_body() against the direct sum over the bodies, for unequal
  // radii and moduli, both orders of the bodies.
  for (const bool sphere : {false, true})
    for (const auto &[b1, b2] : dissimilar_pairs(sphere))
      {
        CAPTURE(sphere, b2.radius / b1.radius, b2.modulus / b1.modulus);
        const ForceLaw law     = two_body_force_law(sphere, b1, b2);
        const ForceLaw swapped = two_body_force_law(sphere, b2, b1);
        for (const double x : {1e-7, 1e-4, 1e-3, 1e-2})
          {
            CAPTURE(x);
            const double force = x * force_unit(sphere, b1);
            const double delta = approach(sphere, force, b1, b2);
            CHECK(approach(sphere, force, b2, b1) ==
                  Approx(delta).epsilon(1e-13));
            CHECK(law.force(delta) == Approx(force).epsilon(1e-10));
            CHECK(swapped.force(delta) == Approx(force).epsilon(1e-10));
          }
      }
}

TEST_CASE("Two bodies: F' is the derivative of F", "[reference][two body]")
{
  for (const bool sphere : {false, true})
    for (const auto &[b1, b2] : dissimilar_pairs(sphere))
      {
        CAPTURE(sphere, b2.radius / b1.radius, b2.modulus / b1.modulus);
        const ForceLaw law = two_body_force_law(sphere, b1, b2);
        for (const double d : {1e-5, 1e-3, 1e-2})
          {
            const double delta = d * R, h = 1e-4 * delta;
            CAPTURE(d);
            // fourth-order central difference
            const double difference =
              (8. * (law.force(delta + h) - law.force(delta - h)) -
               (law.force(delta + 2. * h) - law.force(delta - 2. * h))) /
              (12. * h);
            CHECK(law.derivative(delta) == Approx(difference).epsilon(1e-8));
          }
      }
}

TEST_CASE("Two bodies: a large stiff partner is the wall",
          "[reference][two body]")
{
  const double infinity = std::numeric_limits<double>::infinity();
  for (const bool sphere : {false, true})
    {
      CAPTURE(sphere);
      const ContactBody b{R, E, sphere ? sphere_constant : disk_constant()};
      const ForceLaw    wall = wall_law(sphere, b);
      // The partner's radius and modulus 1e12 times the body's: its own
      // compliance adds 1e-12 ln(4e12) relative to the body's.
      const ForceLaw near_wall =
        two_body_force_law(sphere, b, {1e12 * R, 1e12 * E, 0.7});
      // A rigid flat partner is the wall itself.
      const ForceLaw rigid_flat =
        two_body_force_law(sphere, {infinity, infinity, 0.}, b);
      for (const double d : {1e-6, 1e-4, 1e-2, 0.05})
        {
          const double delta = d * R;
          CAPTURE(d);
          CHECK(near_wall.force(delta) ==
                Approx(wall.force(delta)).epsilon(1e-9));
          CHECK(near_wall.derivative(delta) ==
                Approx(wall.derivative(delta)).epsilon(1e-9));
          CHECK(rigid_flat.force(delta) ==
                Approx(wall.force(delta)).epsilon(1e-13));
        }
    }
  // An elastic sphere may be flat (a half-space), an elastic disk not.
  CHECK_NOTHROW(two_body_force_law(true, {R, E, 0.}, {infinity, E, 0.}));
  CHECK_THROWS_AS(two_body_force_law(false, {R, E, 0.}, {infinity, E, 0.}),
                  std::invalid_argument);
}

TEST_CASE("Two bodies: identical bodies' impact is the wall impact",
          "[reference][two body]")
{
  // mu = m / 2 and relative speed 2 v: the overlap is twice the wall
  // approach, xi = 2 delta, and the contact time is the wall's.
  const double c = std::sqrt(E / density);
  for (const double v : {1e-3 * c, 1e-2 * c, 0.1 * c})
    {
      CAPTURE(v / c);
      {
        const double       mass = density * M_PI * R * R;
        const ContactBody  b{R, E, disk_constant()};
        const OneDofImpact wall = one_dof_impact(v, mass, E, R, b.constant);
        const OneDofImpact pair =
          two_body_elastic_impact(false, 0.5 * mass, 2. * v, b, b);
        CHECK(pair.contact_time == Approx(wall.contact_time).epsilon(1e-9));
        CHECK(pair.max_compression ==
              Approx(2. * wall.max_compression).epsilon(1e-9));
        CHECK(pair.max_force == Approx(wall.max_force).epsilon(1e-9));
      }
      const double mass = density * 4. / 3. * M_PI * R * R * R;
      {
        const ContactBody  b{R, E, 0.};
        const HertzImpact  wall = hertz_sphere_impact(mass, E, R, v);
        const OneDofImpact pair =
          two_body_elastic_impact(true, 0.5 * mass, 2. * v, b, b);
        CHECK(pair.contact_time == Approx(wall.contact_time).epsilon(1e-9));
        CHECK(pair.max_compression ==
              Approx(2. * wall.max_overlap).epsilon(1e-9));
        CHECK(pair.max_force == Approx(wall.max_force).epsilon(1e-9));
      }
      {
        const ContactBody  b{R, E, sphere_constant};
        const OneDofImpact wall =
          wall_contact_theory(true)->elastic_impact(mass, v, E, R, b.constant);
        const OneDofImpact pair =
          two_body_elastic_impact(true, 0.5 * mass, 2. * v, b, b);
        CHECK(pair.contact_time == Approx(wall.contact_time).epsilon(1e-9));
        CHECK(pair.max_compression ==
              Approx(2. * wall.max_compression).epsilon(1e-9));
      }
    }
}

TEST_CASE("Two bodies: the largest approach and the law's range",
          "[reference][two body]")
{
  for (const bool sphere : {false, true})
    for (const auto &[b1, b2] : dissimilar_pairs(sphere))
      {
        CAPTURE(sphere, b2.radius / b1.radius, b2.modulus / b1.modulus);
        // The closed form is the largest value of the direct sum.
        const double largest = two_body_largest_approach(sphere, b1, b2);
        double       highest = 0.;
        for (double x = 1e-3; x < 1e3; x *= 1.001)
          highest =
            std::max(highest,
                     approach(sphere, x * force_unit(sphere, b1), b1, b2));
        CHECK(highest <= largest * (1. + 1e-14));
        CHECK(highest == Approx(largest).epsilon(1e-6));

        const ForceLaw law = two_body_force_law(sphere, b1, b2);
        CHECK_NOTHROW(law.force(0.999 * largest));
        CHECK_THROWS_AS(law.force(1.001 * largest), std::domain_error);
        CHECK_THROWS_AS(law.derivative(1.001 * largest), std::domain_error);
      }
  // Spheres with D_eff >= 0 have no largest approach.
  CHECK(
    std::isinf(two_body_largest_approach(true, {R, E, 0.}, {0.5 * R, E, 0.3})));

  // An impact refused exactly when mu v^2 / 2 reaches V = int_0^top F.
  for (const bool sphere : {false, true})
    {
      CAPTURE(sphere);
      const auto [b1, b2]    = dissimilar_pairs(sphere)[4];
      const ForceLaw law     = two_body_force_law(sphere, b1, b2);
      const double   largest = two_body_largest_approach(sphere, b1, b2);
      const double   energy =
        boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
          law.force, 0., largest * (1. - 1e-12), 10, 1e-13);
      const double mu = 0.8, critical = std::sqrt(2. * energy / mu);
      const auto   impact =
        two_body_elastic_impact(sphere, mu, 0.999 * critical, b1, b2);
      CHECK(impact.max_compression < largest);
      CHECK(impact.max_compression > 0.999 * largest);
      CHECK_THROWS_AS(
        two_body_elastic_impact(sphere, mu, 1.001 * critical, b1, b2),
        std::domain_error);
    }
  const ContactBody disk{R, E, disk_constant()};
  const double      mass = density * M_PI * R * R;
  CHECK_NOTHROW(two_body_elastic_impact(
    false, 0.5 * mass, 0.3 * std::sqrt(E / density), disk, disk));
  CHECK_THROWS_AS(two_body_elastic_impact(false,
                                          0.5 * mass,
                                          10. * std::sqrt(E / density),
                                          disk,
                                          disk),
                  std::domain_error);

  CHECK_THROWS_AS(two_body_force_law(false, {-R, E, 0.}, disk),
                  std::invalid_argument);
  CHECK_THROWS_AS(two_body_force_law(false, disk, {R, 0., 0.}),
                  std::invalid_argument);
  CHECK_THROWS_AS(two_disk_approach(-1., disk, disk), std::invalid_argument);
  const double infinity = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(two_body_force_law(true,
                                     {R, infinity, 0.},
                                     {R, infinity, 0.}),
                  std::invalid_argument);
  CHECK_THROWS_AS(two_body_force_law(true,
                                     {infinity, E, 0.},
                                     {infinity, E, 0.}),
                  std::invalid_argument);
}

TEST_CASE("Two bodies: each body's constant and the pair's are read back "
          "from the approaches",
          "[reference][two body]")
{
  // wall_law_constant() inverts one body's term of the sum, and applied to
  // the whole approach with the equivalent body's radius and modulus it
  // gives C_eff (D_eff): the pair is that body on a wall.
  for (const bool sphere : {false, true})
    for (const auto &[b1, b2] : dissimilar_pairs(sphere))
      {
        CAPTURE(sphere, b2.radius / b1.radius, b2.modulus / b1.modulus);
        const ContactBody equivalent = equivalent_body(sphere, b1, b2);
        for (const double x : {1e-6, 1e-3})
          {
            CAPTURE(x);
            const double force = x * force_unit(sphere, b1);
            const double a     = two_body_half_width(sphere, force, b1, b2);
            for (const ContactBody *b : {&b1, &b2})
              {
                // One body's share: its term of the sum at the common a.
                const double share =
                  sphere ? 0.75 * force / (a * b->modulus) +
                             b->constant * force / (b->modulus * b->radius) :
                           force / (M_PI * b->modulus) *
                             (2. * std::log(4. * b->radius / a) + b->constant);
                CHECK(wall_law_constant(sphere, force, share, a, *b) ==
                      Approx(b->constant).margin(1e-10));
              }
            CHECK(wall_law_constant(sphere,
                                    force,
                                    approach(sphere, force, b1, b2),
                                    a,
                                    equivalent) ==
                  Approx(equivalent.constant).margin(1e-10));
          }
      }
  CHECK_THROWS_AS(wall_law_constant(false, 0., 1., 1., {1., 1., 0.}),
                  std::invalid_argument);
}
