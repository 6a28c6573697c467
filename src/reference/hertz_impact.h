#pragma once

#include "reference/collision_ode.h"

namespace DiskImpact
{
  namespace Reference
  {
    /// Hertz's elastic impact of a sphere on a rigid wall, in closed form.
    struct HertzImpact
    {
      double max_overlap  = 0.; ///< delta_max
      double contact_time = 0.; ///< t_c
      double max_force    = 0.; ///< F(delta_max)
    };

    /// The stiffness rho of Hertz's law F = rho delta^{3/2} of a sphere of
    /// radius @p radius on a rigid wall: rho = (4/3) E* sqrt(R).
    double
    hertz_sphere_stiffness(double effective_modulus, double radius);

    /**
     * The 1-DOF Hertz impact m delta'' = -rho delta^{3/2} from delta = 0,
     * delta' = v: the energy m v^2 / 2 = (2/5) rho delta_max^{5/2} gives
     * delta_max = (5 m v^2 / (4 rho))^{2/5}, and the time to it,
     * int_0^{delta_max} d delta / delta' with
     * delta' = v sqrt(1 - (delta / delta_max)^{5/2}), is
     * (delta_max / v) int_0^1 (1 - x^{5/2})^{-1/2} dx
     * = (delta_max / v) (2/5) B(2/5, 1/2); the contact time is twice that,
     * t_c = 2.94328 delta_max / v.
     */
    HertzImpact
    hertz_sphere_impact(double mass,
                        double effective_modulus,
                        double radius,
                        double velocity);

    /**
     * The wall law of a finite sphere as a force law for collide(): the
     * approach of the centre of mass delta = delta_H(P) + D P / (E* R), with
     * Hertz's delta_H = (9 P^2 / (16 R E*^2))^{1/3} and the finite-size
     * constant @p finite_size_constant D (docs/theory/sphere-finite-size.md);
     * D = 0 is Hertz's F = (4/3) E* sqrt(R) delta^{3/2}. In the load
     * x = P / (pi E* R^2) and d = delta / R: d = (3 pi x / 4)^{2/3} + pi D x,
     * inverted numerically.
     * For D < 0 the law holds up to the largest approach, where
     * dd/dx = 0; beyond it the force throws std::domain_error.
     */
    ForceLaw
    sphere_force_law(double effective_modulus,
                     double radius,
                     double finite_size_constant);
  } // namespace Reference
} // namespace DiskImpact
