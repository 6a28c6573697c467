#include "reference/free_disk_mode_shapes.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/bessel_prime.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    namespace
    {
      /// J_n(x), J_n'(x), J_n''(x) and J_n(x) / x (n >= 1; 0 for n = 0).
      struct BesselValues
      {
        double j, dj, ddj, j_over_x;
      };

      BesselValues
      bessel_values(const unsigned int n, const double x)
      {
        BesselValues b;
        b.j  = boost::math::cyl_bessel_j(n, x);
        b.dj = boost::math::cyl_bessel_j_prime(n, x);
        // J_n(x) / x = (J_{n-1}(x) + J_{n+1}(x)) / (2 n), regular at x = 0
        b.j_over_x = n == 0 ? 0. :
                              (boost::math::cyl_bessel_j(n - 1, x) +
                               boost::math::cyl_bessel_j(n + 1, x)) /
                                (2. * n);
        // Bessel's equation: J'' = -J'/x - (1 - n^2/x^2) J
        b.ddj = x > 0. ? -b.dj / x - b.j + double(n) * n * b.j_over_x / x : 0.;
        return b;
      }
    } // namespace

    std::vector<LabelledKappa>
    lowest_symmetric_modes(const FreeDiskModes &modes,
                           const unsigned int   n_modes)
    {
      std::vector<LabelledKappa> found;
      for (const ModeLabel &label : modes.lowest_modes(n_modes, true))
        found.push_back({label, modes.kappa(label)});
      return found;
    }

    FreeDiskModeShape::FreeDiskModeShape(const double in_plane_poisson_ratio,
                                         const double radius,
                                         const ModeLabel &mode_label,
                                         const double     kappa)
        : nu2(in_plane_poisson_ratio)
        , R(radius)
        , mode(mode_label)
        , k(kappa / radius)
        , k_prime(kappa * std::sqrt(2. / (1. - in_plane_poisson_ratio)) /
                  radius)
    {
      if ((mode.family != ModeFamily::radial || mode.n != 0) &&
          (mode.family != ModeFamily::mixed || mode.n == 0))
        throw std::invalid_argument(
          "FreeDiskModeShape: only the radial (n = 0) and mixed (n >= 1) "
          "families are symmetric about the impact axis");
      if (!(kappa > 0.) || !(R > 0.))
        throw std::invalid_argument("FreeDiskModeShape: need kappa, R > 0");

      if (mode.n == 0)
        {
          A = 1.;
          B = 0.;
        }
      else
        {
          // Null vector of the 2x2 boundary matrix: orthogonal to its
          // larger row (the rows are parallel at an eigenfrequency).
          const auto a_part = tractions(profile(R, 1., 0.));
          const auto b_part = tractions(profile(R, 0., 1.));
          if (std::hypot(a_part.first, b_part.first) >=
              std::hypot(a_part.second, b_part.second))
            {
              A = b_part.first;
              B = -a_part.first;
            }
          else
            {
              A = b_part.second;
              B = -a_part.second;
            }
        }

      const double norm = std::sqrt(angular_norm_factor() *
                                    radial_mass_integral() / (M_PI * R * R));
      const auto   edge = profile(R);
      const double sign = std::abs(edge.u_r) >= std::abs(edge.u_phi) ?
                            (edge.u_r >= 0. ? 1. : -1.) :
                            (edge.u_phi >= 0. ? 1. : -1.);
      A *= sign / norm;
      B *= sign / norm;
    }

    const ModeLabel &
    FreeDiskModeShape::label() const
    {
      return mode;
    }

    double
    FreeDiskModeShape::kappa() const
    {
      return k * R;
    }

    std::pair<double, double>
    FreeDiskModeShape::coefficients() const
    {
      return {A, B};
    }

    RadialProfile
    FreeDiskModeShape::profile(const double r) const
    {
      return profile(r, A, B);
    }

    RadialProfile
    FreeDiskModeShape::profile(const double r,
                               const double a,
                               const double b) const
    {
      const unsigned int n  = mode.n;
      const auto         jl = bessel_values(n, k * r);
      const auto         jt = bessel_values(n, k_prime * r);
      // J_n(k r) / r and its r-derivative (k J_n'(k r) - J_n(k r) / r) / r
      const double jl_r  = k * jl.j_over_x;
      const double jt_r  = k_prime * jt.j_over_x;
      const double djl_r = r > 0. ? (k * jl.dj - jl_r) / r : 0.;
      const double djt_r = r > 0. ? (k_prime * jt.dj - jt_r) / r : 0.;

      RadialProfile p;
      p.u_r       = a * k * jl.dj + n * b * jt_r;
      p.du_r_dr   = a * k * k * jl.ddj + n * b * djt_r;
      p.u_phi     = -(n * a * jl_r + b * k_prime * jt.dj);
      p.du_phi_dr = -(n * a * djl_r + b * k_prime * k_prime * jt.ddj);
      return p;
    }

    std::pair<double, double>
    FreeDiskModeShape::tractions(const RadialProfile &p) const
    {
      // sigma = 2 mu eps + lambda tr(eps) I with the in-plane constants:
      // lambda / mu = 2 nu2 / (1 - nu2), mu / E2 = 1 / (2 (1 + nu2)).
      const double       lambda_over_mu = 2. * nu2 / (1. - nu2);
      const double       mu_over_e      = 0.5 / (1. + nu2);
      const unsigned int n              = mode.n;
      const double       s_rr           = (lambda_over_mu + 2.) * p.du_r_dr +
                          lambda_over_mu * (p.u_r + n * p.u_phi) / R;
      const double s_rphi = p.du_phi_dr - (p.u_phi + n * p.u_r) / R;
      return {mu_over_e * R * s_rr, mu_over_e * R * s_rphi};
    }

    double
    FreeDiskModeShape::edge_radial_amplitude() const
    {
      return profile(R).u_r;
    }

    double
    FreeDiskModeShape::edge_tangential_amplitude() const
    {
      return profile(R).u_phi;
    }

    std::pair<double, double>
    FreeDiskModeShape::boundary_tractions() const
    {
      return tractions(profile(R));
    }

    double
    FreeDiskModeShape::angular_norm_factor() const
    {
      return mode.n == 0 ? 2. * M_PI : M_PI;
    }

    double
    FreeDiskModeShape::radial_mass_integral() const
    {
      // One 20-point panel per 4 radians of the faster-varying phase k' r:
      // the integrand is smooth and the rule exact to degree 39 per panel.
      const unsigned int panels =
        1 + static_cast<unsigned int>(k_prime * R / 4.);
      const double h         = R / panels;
      auto         integrand = [this](const double r) {
        const auto p = profile(r);
        return r * (p.u_r * p.u_r + p.u_phi * p.u_phi);
      };
      double sum = 0.;
      for (unsigned int i = 0; i < panels; ++i)
        sum +=
          boost::math::quadrature::gauss<double, 20>::integrate(integrand,
                                                                i * h,
                                                                (i + 1) * h);
      return sum;
    }

    std::vector<FreeDiskModeShape>
    symmetric_mode_shapes(const double       in_plane_poisson_ratio,
                          const unsigned int n_modes)
    {
      const double        nu2 = in_plane_poisson_ratio;
      const FreeDiskModes modes(nu2, 1. / std::sqrt(1. - nu2 * nu2), 1.);
      std::vector<FreeDiskModeShape> shapes;
      for (const auto &[label, kappa] : lowest_symmetric_modes(modes, n_modes))
        shapes.emplace_back(nu2, 1., label, kappa);
      return shapes;
    }
  } // namespace Reference
} // namespace DiskImpact
