#include "restitution/restitution_fit.h"

#include "reference/dem_contact_models.h"
#include "reference/hertz_first_yield.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/householder.h>
#include <deal.II/lac/vector.h>

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace DiskImpact
{
  using namespace dealii;

  double
  SmoothFit::operator()(const double v) const
  {
    const double x   = std::pow(v / v_ref, 0.2);
    double       sum = 0., power = 1.;
    for (const double coefficient : a)
      sum += coefficient * (power *= x);
    return 1. - sum;
  }

  std::vector<double>
  fit_weights(const std::vector<double> &error)
  {
    std::vector<double> finite;
    for (const double e : error)
      if (e > 0. && std::isfinite(e))
        finite.push_back(e);
    std::sort(finite.begin(), finite.end());
    const double typical = finite.empty() ? 1. : finite[finite.size() / 2];
    std::vector<double> w;
    for (const double e : error)
      w.push_back(1. / (e > 0. && std::isfinite(e) ? e : typical));
    return w;
  }

  SmoothFit
  fit_smooth(const RestitutionTable &table,
             const double            v_ref,
             unsigned int            terms)
  {
    const unsigned int n = table.v.size();
    terms                = std::min<unsigned int>(terms, std::max(1u, n - 1));
    const auto         w = fit_weights(table.error);
    FullMatrix<double> design(n, terms);
    Vector<double>     rhs(n), a(terms);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double x     = std::pow(table.v[i] / v_ref, 0.2);
        double       power = 1.;
        for (unsigned int k = 0; k < terms; ++k)
          design(i, k) = w[i] * (power *= x);
        rhs[i] = w[i] * (1. - table.epsilon[i]);
      }
    Householder<double>(design).least_squares(a, rhs);
    return {v_ref, std::vector<double>(a.begin(), a.end())};
  }

  namespace
  {
    /// The minimum of @p f over [@p low, @p high]: a scan of @p n_scan
    /// steps brackets it (the misfits here are flat or have several
    /// valleys), Brent's method refines it. Returns (argument, value).
    std::pair<double, double>
    scan_and_minimize(const std::function<double(double)> &f,
                      const double                         low,
                      const double                         high,
                      const unsigned int                   n_scan)
    {
      const double step = (high - low) / n_scan;
      double       best = low, best_value = f(low);
      for (unsigned int k = 1; k <= n_scan; ++k)
        if (const double value = f(low + k * step); value < best_value)
          {
            best_value = value;
            best       = low + k * step;
          }
      boost::uintmax_t iterations = 100;
      return boost::math::tools::brent_find_minima(f,
                                                   std::max(low, best - step),
                                                   std::min(high, best + step),
                                                   40,
                                                   iterations);
    }
  } // namespace

  ThorntonFit
  fit_thornton(const RestitutionTable &table, const double yield_strain)
  {
    ThorntonFit fit;
    const auto  model = [&](const double log_ratio) {
      fit.pressure_ratio = std::exp(log_ratio);
      fit.yield_speed =
        Reference::sphere_yield_velocity(fit.pressure_ratio, yield_strain);
      fit.epsilon.clear();
      double sum = 0.;
      for (unsigned int i = 0; i < table.v.size(); ++i)
        {
          fit.epsilon.push_back(
            Reference::thornton_ning_epsilon(table.v[i] / fit.yield_speed));
          sum += std::pow(fit.epsilon.back() - table.epsilon[i], 2);
        }
      return sum;
    };
    // The misfit is flat where every speed is below the model's v_y.
    model(scan_and_minimize(model, std::log(0.3), std::log(30.), 60).first);
    for (unsigned int i = 0; i < table.v.size(); ++i)
      fit.max_residual =
        std::max(fit.max_residual, std::abs(fit.epsilon[i] - table.epsilon[i]));
    return fit;
  }

  LudingFit
  fit_luding(const RestitutionTable &table)
  {
    LudingFit fit;
    // Beyond v_p the model's epsilon rises again toward 1: v_p at the
    // highest speed keeps it falling over the whole table.
    fit.plastic_speed = *std::max_element(table.v.begin(), table.v.end());
    const auto misfit = [&](const double log_excess) {
      double sum = 0.;
      for (unsigned int i = 0; i < table.v.size(); ++i)
        sum +=
          std::pow(Reference::luding_epsilon(table.v[i] / fit.plastic_speed,
                                             std::exp(log_excess)) -
                     table.epsilon[i],
                   2);
      return sum;
    };
    const double excess = std::exp(
      scan_and_minimize(misfit, std::log(1e-3), std::log(1e3), 60).first);
    fit.stiffness_ratio = 1. + excess;
    for (unsigned int i = 0; i < table.v.size(); ++i)
      {
        fit.epsilon.push_back(
          Reference::luding_epsilon(table.v[i] / fit.plastic_speed, excess));
        fit.max_residual =
          std::max(fit.max_residual,
                   std::abs(fit.epsilon.back() - table.epsilon[i]));
      }
    return fit;
  }

  double
  interpolate_in_log(const std::vector<double> &x,
                     const std::vector<double> &y,
                     const double               x0)
  {
    if (x0 <= x.front())
      return y.front();
    for (unsigned int i = 1; i < x.size(); ++i)
      if (x0 <= x[i])
        {
          const double s = std::log(x0 / x[i - 1]) / std::log(x[i] / x[i - 1]);
          return (1. - s) * y[i - 1] + s * y[i];
        }
    return y.back();
  }
} // namespace DiskImpact
