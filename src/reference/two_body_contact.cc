#include "reference/two_body_contact.h"

#include "reference/hertz_impact.h"
#include "reference/log_contact_law.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace DiskImpact
{
  namespace Reference
  {
    namespace
    {
      /// Throws std::invalid_argument unless the pair has a finite law.
      void
      check_pair(const bool         sphere,
                 const ContactBody &b1,
                 const ContactBody &b2)
      {
        for (const ContactBody *b : {&b1, &b2})
          {
            if (!(b->radius > 0.) || !(b->modulus > 0.))
              throw std::invalid_argument(
                "two-body contact: radii and moduli must be positive");
            if (!std::isfinite(b->constant))
              throw std::invalid_argument(
                "two-body contact: the wall-law constants must be finite");
            if (!sphere && std::isinf(b->radius) && std::isfinite(b->modulus))
              throw std::invalid_argument(
                "two-body contact: an elastic flat disk (a half-plane) has "
                "no finite approach");
          }
        if (std::isinf(b1.radius) && std::isinf(b2.radius))
          throw std::invalid_argument(
            "two-body contact: at least one body must be curved");
        if (std::isinf(b1.modulus) && std::isinf(b2.modulus))
          throw std::invalid_argument(
            "two-body contact: at least one body must be deformable");
      }

      /// 1 / (1 / a + 1 / b), a or b infinite allowed.
      double
      harmonic_sum(const double a, const double b)
      {
        return 1. / (1. / a + 1. / b);
      }

      /// The largest approach of a wall law (of equivalent_body()) and the
      /// energy V = int_0^delta F stored up to it; infinite if it has none.
      struct LawTop
      {
        double approach = std::numeric_limits<double>::infinity();
        double energy   = std::numeric_limits<double>::infinity();
      };

      LawTop
      law_top(const bool sphere, const ContactBody &eq)
      {
        LawTop       top;
        const double E = eq.modulus, R = eq.radius, c = eq.constant;
        if (!sphere)
          {
            // x_top = 4 e^{C - 1} = d_top; V = P delta / 2 - P^2 / (4 pi E)
            // (integrate delta = P (alpha - beta ln P) by parts).
            const double x = LogContactLaw(c).maximum_compression();
            const double P = M_PI * E * R * x;
            top.approach   = R * x;
            top.energy     = 0.5 * P * top.approach - P * P / (4. * M_PI * E);
          }
        else if (c < 0.)
          {
            // d(x) = (3 pi x / 4)^{2/3} + pi D x is largest at
            // P = E R^2 / (6 (-D)^3), where delta = R / (12 D^2);
            // V = 2 P delta / 5 + D P^2 / (10 E R).
            const double P = E * R * R / (6. * std::pow(-c, 3));
            top.approach   = R / (12. * c * c);
            top.energy     = 0.4 * P * top.approach + c * P * P / (10. * E * R);
          }
        return top;
      }
    } // namespace

    ContactBody
    equivalent_body(const bool         sphere,
                    const ContactBody &b1,
                    const ContactBody &b2)
    {
      check_pair(sphere, b1, b2);
      ContactBody eq;
      eq.radius   = harmonic_sum(b1.radius, b2.radius);
      eq.modulus  = harmonic_sum(b1.modulus, b2.modulus);
      eq.constant = 0.;
      for (const ContactBody *b : {&b1, &b2})
        {
          const double w = eq.modulus / b->modulus;
          if (w == 0.) // rigid: no deformation, no term
            continue;
          eq.constant +=
            sphere ? w * (eq.radius / b->radius) * b->constant :
                     w * (b->constant + 2. * std::log(b->radius / eq.radius));
        }
      return eq;
    }

    double
    two_body_half_width(const bool         sphere,
                        const double       force,
                        const ContactBody &b1,
                        const ContactBody &b2)
    {
      check_pair(sphere, b1, b2);
      if (!(force >= 0.))
        throw std::invalid_argument(
          "two_body_half_width: the force must not be negative");
      const double R = harmonic_sum(b1.radius, b2.radius);
      const double E = harmonic_sum(b1.modulus, b2.modulus);
      return sphere ? std::cbrt(0.75 * force * R / E) :
                      std::sqrt(4. * force * R / (M_PI * E));
    }

    double
    two_disk_approach(const double       force,
                      const ContactBody &b1,
                      const ContactBody &b2)
    {
      const double a = two_body_half_width(false, force, b1, b2);
      if (force == 0.)
        return 0.;
      double delta = 0.;
      for (const ContactBody *b : {&b1, &b2})
        if (std::isfinite(b->modulus))
          delta += force / (M_PI * b->modulus) *
                   (2. * std::log(4. * b->radius / a) + b->constant);
      return delta;
    }

    double
    wall_law_constant(const bool         sphere,
                      const double       force,
                      const double       approach,
                      const double       a,
                      const ContactBody &body)
    {
      if (!(force > 0.) || !(a > 0.))
        throw std::invalid_argument(
          "wall_law_constant: the force and the half-width must be positive");
      const double E = body.modulus, R = body.radius;
      if (sphere)
        return (approach - 0.75 * force / (a * E)) * E * R / force;
      return M_PI * E * approach / force - 2. * std::log(4. * R / a);
    }

    double
    two_sphere_approach(const double       force,
                        const ContactBody &b1,
                        const ContactBody &b2)
    {
      const double a     = two_body_half_width(true, force, b1, b2);
      double       delta = a * a / harmonic_sum(b1.radius, b2.radius);
      for (const ContactBody *b : {&b1, &b2})
        delta += b->constant * force / (b->modulus * b->radius);
      return delta;
    }

    double
    two_body_largest_approach(const bool         sphere,
                              const ContactBody &b1,
                              const ContactBody &b2)
    {
      return law_top(sphere, equivalent_body(sphere, b1, b2)).approach;
    }

    ForceLaw
    two_body_force_law(const bool         sphere,
                       const ContactBody &b1,
                       const ContactBody &b2)
    {
      const ContactBody eq      = equivalent_body(sphere, b1, b2);
      const double      largest = law_top(sphere, eq).approach;
      const ForceLaw    wall =
        sphere ? sphere_force_law(eq.modulus, eq.radius, eq.constant) :
                    disk_force_law(eq.modulus, eq.radius, eq.constant);
      auto check = [largest](const double delta) {
        if (!(delta < largest))
          throw std::domain_error(
            "two_body_force_law: the approach " + std::to_string(delta) +
            " exceeds the law's largest, " + std::to_string(largest));
      };
      return {[=](const double delta) {
                if (!(delta > 0.))
                  return 0.;
                check(delta);
                return wall.force(delta);
              },
              [=](const double delta) {
                if (!(delta > 0.))
                  return 0.;
                check(delta);
                return wall.derivative(delta);
              }};
    }

    OneDofImpact
    two_body_elastic_impact(const bool         sphere,
                            const double       reduced_mass,
                            const double       relative_speed,
                            const ContactBody &b1,
                            const ContactBody &b2)
    {
      if (!(reduced_mass > 0.) || !(relative_speed > 0.))
        throw std::invalid_argument(
          "two_body_elastic_impact: the reduced mass and the relative speed "
          "must be positive");
      const double energy =
        0.5 * reduced_mass * relative_speed * relative_speed;
      if (!(energy < law_top(sphere, equivalent_body(sphere, b1, b2)).energy))
        throw std::domain_error(
          "two_body_elastic_impact: the relative speed is too high for the "
          "law (the approach would pass its largest)");
      const auto law       = two_body_force_law(sphere, b1, b2);
      const auto collision = collide(
        reduced_mass, relative_speed, law, 0., EndCriterion::overlap, 1e-12);
      OneDofImpact impact;
      impact.contact_time    = collision.contact_time;
      impact.max_compression = collision.max_overlap;
      impact.max_force       = law.force(collision.max_overlap);
      return impact;
    }
  } // namespace Reference
} // namespace DiskImpact
