#include "reference/schwager_disk.h"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/lambert_w.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    namespace
    {
      /**
       * q = 2 y^2 ln y / (1 - y^2) at y = sin(theta), in [-1, 0]; near
       * y = 1 it is written with log1p(-cos^2) so that it tends to -1
       * without cancellation.
       */
      double
      log_ratio(const double theta)
      {
        const double s = std::sin(theta), c = std::cos(theta);
        if (s * s == 0.)
          return 0.;
        if (c * c == 0.)
          return -1.;
        const double log_y_squared =
          s < 0.5 ? 2. * std::log(s) : std::log1p(-c * c);
        return s * s * log_y_squared / (c * c);
      }

      /// int_0^{pi/2} cos^2(theta) g(theta) d theta, the weight
      /// dy sqrt(1 - y^2) of eqs. 41-48 at y = sin(theta).
      template <typename Integrand>
      double
      integrate_over_quarter_circle(const Integrand &g)
      {
        boost::math::quadrature::tanh_sinh<double> integrator;
        return integrator.integrate(
          [&](const double theta) {
            const double c = std::cos(theta);
            return c * c * g(theta);
          },
          0.,
          M_PI / 2.,
          1e-14);
      }
    } // namespace

    std::vector<double>
    schwager_c_coefficients(const unsigned int n)
    {
      std::vector<double> c(n);
      double              a = 1.; // a_k = binomial(1/2, k)
      for (unsigned int k = 0; k < n; ++k)
        {
          if (k > 0)
            a *= (1.5 - k) / k;
          c[k] = a * integrate_over_quarter_circle([k](const double theta) {
                   return std::pow(log_ratio(theta), k);
                 });
        }
      return c;
    }

    double
    schwager_c0_closed_form()
    {
      return M_PI / 4.;
    }

    double
    schwager_c1_closed_form()
    {
      return M_PI * (1. - std::log(4.)) / 8.;
    }

    std::vector<double>
    schwager_d_coefficients(const std::vector<double> &c)
    {
      std::vector<double> d(c.size(), 0.);
      for (unsigned int k = 0; k < c.size(); ++k)
        {
          for (unsigned int i = 0; i + 1 <= k; ++i)
            d[k] -= 2. * (k - i - 1.) * c[i] * c[k - i - 1];
          for (unsigned int i = 0; i <= k; ++i)
            d[k] -= c[i] * c[k - i];
        }
      return d;
    }

    double
    schwager_maximum_scaled_velocity()
    {
      return 1. / (std::sqrt(2.) * M_E);
    }

    double
    schwager_scaled_velocity(const double impact_speed_over_wave_speed,
                             const double constant)
    {
      return impact_speed_over_wave_speed * std::exp(-constant) / 4.;
    }

    double
    schwager_scaled_damping(const double relaxation_time,
                            const double wave_speed,
                            const double radius)
    {
      return relaxation_time * wave_speed / radius;
    }

    double
    schwager_series_variable(const double scaled_velocity)
    {
      const double v = scaled_velocity;
      if (!(v > 0.) || !(v <= schwager_maximum_scaled_velocity()))
        throw std::domain_error(
          "Schwager disk restitution: the scaled velocity must lie in "
          "(0, 1 / (sqrt(2) e)], where the log law can stop the disk");
      // -2 e v^2 may round below -1/e at v = v_max.
      const double argument = std::max(-2. * M_E * v * v, -std::exp(-1.));
      return -boost::math::lambert_wm1(argument);
    }

    SchwagerDiskRestitution::SchwagerDiskRestitution(
      const unsigned int n_coefficients)
        : c(schwager_c_coefficients(n_coefficients))
        , d(schwager_d_coefficients(c))
    {
    }

    const std::vector<double> &
    SchwagerDiskRestitution::c_coefficients() const
    {
      return c;
    }

    const std::vector<double> &
    SchwagerDiskRestitution::d_coefficients() const
    {
      return d;
    }

    double
    SchwagerDiskRestitution::first_order_term(
      const double scaled_velocity) const
    {
      const double u   = schwager_series_variable(scaled_velocity);
      double       sum = 0.;
      for (unsigned int k = 0; k < c.size(); ++k)
        sum += c[k] * std::pow(u, -(k + 0.5));
      return -std::sqrt(8.) * sum;
    }

    double
    SchwagerDiskRestitution::second_order_term(
      const double scaled_velocity) const
    {
      const double u = schwager_series_variable(scaled_velocity);
      if (!(scaled_velocity < schwager_maximum_scaled_velocity()))
        throw std::domain_error(
          "Schwager disk restitution: the second-order term diverges at the "
          "largest scaled velocity 1 / (sqrt(2) e)");
      double sum = 0.;
      for (unsigned int k = 0; k < d.size(); ++k)
        sum += d[k] * std::pow(u, -double(k));
      return 4. / (1. - u) * sum;
    }

    double
    SchwagerDiskRestitution::first_order(const double alpha,
                                         const double scaled_velocity) const
    {
      return 1. + alpha * first_order_term(scaled_velocity);
    }

    double
    SchwagerDiskRestitution::second_order(const double alpha,
                                          const double scaled_velocity) const
    {
      return 1. + alpha * first_order_term(scaled_velocity) +
             alpha * alpha * second_order_term(scaled_velocity);
    }

    double
    SchwagerDiskRestitution::first_order_unexpanded(
      const double alpha,
      const double scaled_velocity)
    {
      const double u = schwager_series_variable(scaled_velocity);
      const double integral =
        integrate_over_quarter_circle([u](const double theta) {
          return std::sqrt(std::max(0., 1. + log_ratio(theta) / u));
        });
      return 1. - 2. * alpha * std::sqrt(2. / u) * integral;
    }

    double
    SchwagerDiskRestitution::end_criterion_difference(
      const double alpha,
      const double scaled_velocity)
    {
      const double argument = -M_E * alpha * scaled_velocity;
      if (!(argument < 0.) || !(argument >= -std::exp(-1.)))
        throw std::domain_error(
          "Schwager disk restitution: the end-criterion difference needs "
          "0 < alpha v <= exp(-2)");
      const double s = boost::math::lambert_wm1(argument);
      return alpha * alpha * (-1. - 2. * s) / (4. * s * s);
    }

    double
    SchwagerDiskRestitution::second_order_force_criterion(
      const double alpha,
      const double scaled_velocity) const
    {
      return second_order(alpha, scaled_velocity) +
             end_criterion_difference(alpha, scaled_velocity);
    }
  } // namespace Reference
} // namespace DiskImpact
