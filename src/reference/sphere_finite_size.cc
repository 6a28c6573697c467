#include "reference/sphere_finite_size.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    std::complex<double>
    digamma(std::complex<double> z)
    {
      if (!(z.real() > 0.))
        throw std::invalid_argument("digamma: needs Re z > 0");
      // psi(z) = psi(z + 1) - 1/z until Re z >= 10.
      std::complex<double> shift = 0.;
      while (z.real() < 10.)
        {
          shift -= 1. / z;
          z += 1.;
        }
      // psi(z) ~ ln z - 1/(2z) - sum_k B_2k / (2k z^2k), to k = 7.
      const std::complex<double> w = 1. / (z * z);
      const std::complex<double> series =
        w * (1. / 12. -
             w * (1. / 120. -
                  w * (1. / 252. -
                       w * (1. / 240. -
                            w * (1. / 132. - w * (691. / 32760. - w / 12.))))));
      return shift + std::log(z) - 0.5 / z - series;
    }

    namespace
    {
      /// sum_{k >= 0} (-1)^k / (k + a) = [psi((a + 1)/2) - psi(a/2)] / 2.
      std::complex<double>
      alternating_sum(const std::complex<double> a)
      {
        return 0.5 * (digamma(0.5 * (a + 1.)) - digamma(0.5 * a));
      }
    } // namespace

    SphereFiniteSize
    sphere_finite_size_constants(const double nu)
    {
      if (!(4. * nu * nu < 3.) || !(nu <= 0.5))
        throw std::invalid_argument(
          "sphere_finite_size_constants: needs -sqrt(3)/2 < nu <= 1/2");
      const double pi = M_PI, ln2 = std::log(2.);
      // Units P = R = E* = 1. The sphere's surface displacement under an
      // inward unit force at the pole and the balancing body force, relative
      // to the centre of mass, is u_rho = sum_m U_m P_m(cos theta),
      // u_theta = sum_m V_m dP_m/dtheta (docs/theory/sphere-finite-size.md).
      // For m >= 2
      //   U_m = -1/pi + k/(m - 1) + k (alpha m + beta) / Q(m),
      //   Q(m) = m^2 + (2 nu + 1) m + nu + 1, k = 1/(4 pi (nu - 1)),
      // and U_m -> -1/pi + D1/m, V_m -> v1/m.
      const double D1 =
        -(1. - 2. * nu) * (1. - 2. * nu) / (2. * pi * (1. - nu));
      const double v1    = (1. - 2. * nu) / (2. * pi * (1. - nu));
      const double U0    = -(1. - 2. * nu) / (4. * pi * (1. - nu * nu));
      const double U1    = -9. * (1. - 2. * nu) / (20. * pi * (1. - nu * nu));
      const double k     = 1. / (4. * pi * (nu - 1.));
      const double alpha = 8. * nu * nu - 8. * nu + 1.;
      const double beta  = 4. * nu * nu - nu - 2.;
      const std::complex<double> root_part =
        0.5 * std::complex<double>(0., std::sqrt(3. - 4. * nu * nu));
      const std::array<std::complex<double>, 2> roots = {
        {-(nu + 0.5) + root_part, -(nu + 0.5) - root_part}};
      // r_m = U_m + 1/pi - D1/m, summed plain and alternating: the sums of
      // k [1/(m-1) - 1/m] are k and k (2 ln 2 - 1); those of the partial
      // fractions A_j [1/(m - rho_j) - 1/m] follow from psi(2) = 1 - gamma.
      const double               r1          = U1 + 1. / pi - D1;
      std::complex<double>       plain       = 1.;
      std::complex<double>       alternating = 2. * ln2 - 1.;
      const std::complex<double> psi2        = digamma(2.);
      for (unsigned int j = 0; j < 2; ++j)
        {
          const std::complex<double> rho = roots[j], other = roots[1 - j];
          const std::complex<double> A = (alpha * rho + beta) / (rho - other);
          plain += A * (psi2 - digamma(2. - rho));
          alternating += A * (alternating_sum(2. - rho) - (1. - ln2));
        }
      const double sum               = r1 + k * plain.real();
      const double alternating_sum_r = -r1 + k * alternating.real();

      // Near the pole the axial displacement into the body is
      // 1/(pi psi) + D1 ln psi + C_h; the Hertz pressure with the flat
      // punch's weight averages ln(|x - s| / a) to L = 2 ln 2 - 19/12.
      const double C_h = -U0 - 1. / pi - D1 * ln2 - sum - v1;
      const double L   = 2. * ln2 - 19. / 12.;

      SphereFiniteSize constants;
      constants.log_coefficient = D1;
      constants.centre_of_mass  = D1 * L + C_h;
      // The far pole moves toward the wall by -u_rho(pi) relative to the
      // centre of mass.
      const double far_pole = -(U0 + 0.5 / pi - D1 * ln2 + alternating_sum_r);
      constants.diameter    = constants.centre_of_mass + far_pole;
      return constants;
    }

    double
    sphere_finite_size_term(const SphereFiniteSize &constants,
                            const double            contact_radius_ratio)
    {
      if (!(contact_radius_ratio > 0.))
        throw std::invalid_argument(
          "sphere_finite_size_term: a / R must be positive");
      return constants.centre_of_mass +
             constants.log_coefficient * std::log(contact_radius_ratio);
    }
  } // namespace Reference
} // namespace DiskImpact
