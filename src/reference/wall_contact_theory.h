#pragma once

#include "reference/collision_ode.h"
#include "reference/one_dof_impact.h"

#include <memory>
#include <string>

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * The quasistatic contact of a body pressed on a rigid wall, in the
     * dimensionless load x = P / P_unit and approach d = delta / R that the
     * task 'quasistatic contact' measures: Hertz's contact size and pressure,
     * and the constant a measured approach defines.
     *
     * - Disk (per unit thickness): P_unit = pi E2 R, a / R = 2 sqrt(x), the
     *   logarithmic law d = x [ln(4 / x) + C] (LogContactLaw).
     * - Sphere: P_unit = pi E* R^2 with E* = E / (1 - nu^2) (= E2), Hertz's
     *   a^3 = 3 P R / (4 E*), i.e. a / R = (3 pi x / 4)^(1/3), and
     *   delta_H = a^2 / R; a finite sphere adds a term of relative order a/R,
     *   d = d_H(x) + pi x D (delta = delta_H + D P / (E* R)), whose constant
     *   D the task measures.
     */
    class WallContactTheory
    {
    public:
      virtual ~WallContactTheory() = default;

      /// P_unit for the in-plane modulus @p e2 (= E*) and radius @p r.
      virtual double
      force_unit(double e2, double r) const = 0;
      /// Hertz's half-width (disk) or contact radius (sphere), a / R.
      virtual double
      half_width(double load) const = 0;
      /// Hertz's pressure at t = (distance from the axis) / R, in units of
      /// pressure_unit().
      virtual double
      pressure(double t, double load) const = 0;
      /// The pressure unit for a total force @p force: P / R (disk, force
      /// per thickness) or P / R^2 (sphere).
      virtual double
      pressure_unit(double force, double r) const = 0;
      /// The constant of the law through (x, d): C (disk) or D (sphere).
      virtual double
      constant_from(double load, double approach) const = 0;
      /// "C" or "D", for column names and tables.
      virtual std::string
      constant_symbol() const = 0;

      /**
       * The 1-DOF model's wall law F(delta) of the centre-of-mass approach
       * with the constant @p constant (the disk's C: force per unit
       * thickness; the sphere's D), for collide().
       */
      virtual ForceLaw
      force_law(double e2, double r, double constant) const = 0;

      /**
       * The elastic 1-DOF impact of a body of mass @p mass at speed
       * @p velocity on force_law(): contact time, largest approach and
       * force. Throws std::domain_error beyond the law's range.
       */
      virtual OneDofImpact
      elastic_impact(double mass,
                     double velocity,
                     double e2,
                     double r,
                     double constant) const = 0;

      /**
       * The 1-DOF impact with Kelvin-Voigt viscosity, m delta'' + F +
       * A delta' F' = 0 with A = @p relaxation_time (the viscous stress
       * tau C : eps_dot is tau times the elastic stress of the velocity, so
       * quasistatically the viscous force is tau dF/dt;
       * docs/theory/viscoelastic-spheres.md), ended when the total force
       * returns to zero (Schwager & Pöschel 2007), or with @p end.
       */
      Collision
      viscous_impact(double       mass,
                     double       velocity,
                     double       e2,
                     double       r,
                     double       constant,
                     double       relaxation_time,
                     EndCriterion end = EndCriterion::force) const;
    };

    /// The theory of the disk (@p sphere false) or of the sphere.
    std::unique_ptr<WallContactTheory>
    wall_contact_theory(bool sphere);

    /// Hertz's approach delta_H / R = (a / R)^2 = (3 pi x / 4)^(2/3) of a
    /// sphere at load x = P / (pi E* R^2).
    double
    hertz_sphere_approach(double load);
  } // namespace Reference
} // namespace DiskImpact
