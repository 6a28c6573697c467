#pragma once

#include <functional>

namespace DiskImpact
{
  namespace Reference
  {
    /// An elastic force law F(xi) of the overlap xi, with its derivative.
    struct ForceLaw
    {
      std::function<double(double)> force;
      std::function<double(double)> derivative;
    };

    /**
     * The disk's log law as a force law: F(xi) = pi E2 R x(xi / R), x the
     * load of LogContactLaw with the constant @p constant, and
     * F'(xi) = pi E2 / (ln(4 / x) + C - 1); zero for xi <= 0.
     */
    ForceLaw
    disk_force_law(double in_plane_young_modulus,
                   double radius,
                   double constant);

    /// When a collision ends.
    enum class EndCriterion
    {
      force, ///< the total force returns to zero (Schwager & Pöschel 2007: the
             ///< correct one)
      overlap ///< the overlap returns to zero (admits attractive forces)
    };

    /// The result of one collision.
    struct Collision
    {
      double epsilon      = 0.; ///< -xi'(t_c) / v
      double contact_time = 0.; ///< t_c
      double max_overlap  = 0.;
    };

    /**
     * The 1-DOF collision m xi'' + F(xi) + A xi' F'(xi) = 0 (Schwager 2007, eq.
     * 4 with the dissipative force of the Kelvin-Voigt kind), from xi = 0, xi'
     * = @p velocity > 0, integrated with Boost.Odeint's Dormand-Prince stepper
     * with dense output (tolerance @p tolerance); the end of the collision is
     * located in the dense output by bisection.
     */
    Collision
    collide(double          mass,
            double          velocity,
            const ForceLaw &law,
            double          dissipation,
            EndCriterion    end,
            double          tolerance = 1e-13);

    /**
     * The dissipative force f_d(xi, xi') of a Kelvin-Voigt body with one
     * relaxation time @p relaxation_time, quasistatic
     * (docs/theory/viscoelastic-spheres.md, "The Kelvin–Voigt unloading
     * law"): u + tau u' is the elastic field of the current load, so while
     * the contact grows (xi' >= 0) the force is
     * F(xi) + tau xi' F'(xi) (Lee and Radok; Ramírez et al.'s eq. 5 with A =
     * tau), and while it shrinks the edge must stay free of tension, which sets
     * the elastic contact of the approach xi + tau xi': F(xi + tau xi')
     * (zero once xi + tau xi' <= 0). Returned as f_d = total - F(xi) for
     * collide().
     */
    std::function<double(double, double)>
    kelvin_voigt_unloading_force(const ForceLaw &law, double relaxation_time);

    /// The same with any dissipative force f_d(xi, xi'):
    /// m xi'' + F(xi) + f_d(xi, xi') = 0.
    Collision
    collide(double                                       mass,
            double                                       velocity,
            const ForceLaw                              &law,
            const std::function<double(double, double)> &dissipative_force,
            EndCriterion                                 end,
            double                                       tolerance = 1e-13);
  } // namespace Reference
} // namespace DiskImpact
