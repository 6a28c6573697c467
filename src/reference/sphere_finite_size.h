#pragma once

#include <complex>

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * The finite-size law of a sphere pressed on the rigid wall by a
     * uniform body force (docs/theory/sphere-finite-size.md):
     *
     *   delta = delta_H(P) + (P / (E* R)) [D0 + D1 ln(a / R)],
     *
     * with Hertz's approach delta_H and contact radius a. D1 follows from
     * the Boussinesq stresses on the curved surface; D0 from the whole
     * sphere's response to a point force at the pole and the balancing body
     * force (Legendre series of Lame's solution, summed in closed form with
     * the digamma function), matched to Hertz's contact.
     */
    struct SphereFiniteSize
    {
      double log_coefficient = 0.; ///< D1 = -(1 - 2 nu)^2 / (2 pi (1 - nu))
      double centre_of_mass  = 0.; ///< D0 of the centre of mass's approach
      double diameter        = 0.; ///< D0 of the axial diameter's shortening
    };

    /// The constants of the finite-size law for Poisson ratio @p nu,
    /// -sqrt(3)/2 < nu <= 1/2; else std::invalid_argument.
    SphereFiniteSize
    sphere_finite_size_constants(double nu);

    /// D = D0 + D1 ln(a / R) of the centre of mass at contact radius
    /// @p contact_radius_ratio a / R > 0.
    double
    sphere_finite_size_term(const SphereFiniteSize &constants,
                            double                  contact_radius_ratio);

    /// The digamma function psi(z) for Re z > 0 (recurrence to Re z >= 10,
    /// then the asymptotic series with Bernoulli numbers to B_14), which
    /// Boost provides for real arguments only. Else std::invalid_argument.
    std::complex<double>
    digamma(std::complex<double> z);
  } // namespace Reference
} // namespace DiskImpact
