#include "reference/wall_contact_theory.h"

#include "reference/hertz_impact.h"
#include "reference/log_contact_law.h"

#include <cmath>

namespace DiskImpact
{
  namespace Reference
  {
    namespace
    {
      /// Hertz's 2D contact and the logarithmic law (Gerl & Zippelius 1999,
      /// eqs. 46-57).
      class DiskTheory : public WallContactTheory
      {
      public:
        double
        force_unit(const double e2, const double r) const override
        {
          return M_PI * e2 * r;
        }
        double
        half_width(const double load) const override
        {
          return hertz_half_width(load);
        }
        double
        pressure(const double t, const double load) const override
        {
          // p = 2 P / (pi a^2) sqrt(a^2 - t^2) (Gerl & Zippelius 1999, eq. 46)
          const double a = half_width(load);
          return std::abs(t) < a ?
                   2. / (M_PI * a * a) * std::sqrt(a * a - t * t) :
                   0.;
        }
        double
        pressure_unit(const double force, const double r) const override
        {
          return force / r;
        }
        double
        constant_from(const double load, const double approach) const override
        {
          return LogContactLaw::constant_from(load, approach);
        }
        std::string
        constant_symbol() const override
        {
          return "C";
        }
        ForceLaw
        force_law(const double e2,
                  const double r,
                  const double constant) const override
        {
          return disk_force_law(e2, r, constant);
        }
        OneDofImpact
        elastic_impact(const double mass,
                       const double velocity,
                       const double e2,
                       const double r,
                       const double constant) const override
        {
          return one_dof_impact(velocity, mass, e2, r, constant);
        }
      };

      /// Hertz's contact of a sphere, with the finite-size term.
      class SphereTheory : public WallContactTheory
      {
      public:
        double
        force_unit(const double e2, const double r) const override
        {
          return M_PI * e2 * r * r;
        }
        double
        half_width(const double load) const override
        {
          return std::cbrt(0.75 * M_PI * load);
        }
        double
        pressure(const double t, const double load) const override
        {
          // p = 3 P / (2 pi a^2) sqrt(1 - t^2 / a^2)
          const double a = half_width(load);
          return std::abs(t) < a ?
                   1.5 / (M_PI * a * a) * std::sqrt(1. - t * t / (a * a)) :
                   0.;
        }
        double
        pressure_unit(const double force, const double r) const override
        {
          return force / (r * r);
        }
        double
        constant_from(const double load, const double approach) const override
        {
          return (approach - hertz_sphere_approach(load)) / (M_PI * load);
        }
        std::string
        constant_symbol() const override
        {
          return "D";
        }
        ForceLaw
        force_law(const double e2,
                  const double r,
                  const double constant) const override
        {
          return sphere_force_law(e2, r, constant);
        }
        OneDofImpact
        elastic_impact(const double mass,
                       const double velocity,
                       const double e2,
                       const double r,
                       const double constant) const override
        {
          OneDofImpact impact;
          if (constant == 0.)
            {
              const auto hertz    = hertz_sphere_impact(mass, e2, r, velocity);
              impact.contact_time = hertz.contact_time;
              impact.max_compression = hertz.max_overlap;
              impact.max_force       = hertz.max_force;
              return impact;
            }
          const auto law = force_law(e2, r, constant);
          const auto collision =
            collide(mass, velocity, law, 0., EndCriterion::overlap, 1e-12);
          impact.contact_time    = collision.contact_time;
          impact.max_compression = collision.max_overlap;
          impact.max_force       = law.force(collision.max_overlap);
          return impact;
        }
      };
    } // namespace

    Collision
    WallContactTheory::viscous_impact(const double       mass,
                                      const double       velocity,
                                      const double       e2,
                                      const double       r,
                                      const double       constant,
                                      const double       relaxation_time,
                                      const EndCriterion end) const
    {
      return collide(mass,
                     velocity,
                     force_law(e2, r, constant),
                     relaxation_time,
                     end,
                     1e-12);
    }

    std::unique_ptr<WallContactTheory>
    wall_contact_theory(const bool sphere)
    {
      if (sphere)
        return std::make_unique<SphereTheory>();
      return std::make_unique<DiskTheory>();
    }

    double
    hertz_sphere_approach(const double load)
    {
      return std::pow(0.75 * M_PI * load, 2. / 3.);
    }
  } // namespace Reference
} // namespace DiskImpact
