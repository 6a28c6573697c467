#include "dynamics/richardson.h"

#include "base/input_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace DiskImpact
{
  RichardsonEstimate
  richardson_estimate(const std::vector<double> &values,
                      const double               ratio,
                      const double               expected_order)
  {
    require(values.size() >= 2 && ratio > 1. && expected_order > 0.,
            "Richardson extrapolation needs two or more values and a "
            "refinement ratio above 1");
    const std::size_t  n  = values.size();
    const double       d2 = values[n - 1] - values[n - 2];
    RichardsonEstimate estimate;
    estimate.extrapolated = values[n - 1];
    estimate.order        = std::numeric_limits<double>::quiet_NaN();
    const double d1       = n < 3 ? 0. : values[n - 2] - values[n - 3];
    estimate.error        = 3. * std::max(std::abs(d1), std::abs(d2)) /
                     (std::pow(ratio, expected_order) - 1.);
    if (n < 3 || d2 == 0.)
      return estimate;

    const double q = d1 / d2;
    if (!(q > 1.))
      return estimate;
    // Monotone convergence: the last difference alone bounds the rest.
    const double order = std::log(q) / std::log(ratio);
    if (order > 2. * expected_order)
      {
        estimate.error =
          3. * std::abs(d2) / (std::pow(ratio, expected_order) - 1.);
        return estimate;
      }
    if (order < 0.5 * expected_order)
      {
        estimate.error = 3. * std::abs(d2) / (q - 1.);
        return estimate;
      }
    estimate.clean        = true;
    estimate.order        = order;
    estimate.extrapolated = values[n - 1] + d2 / (q - 1.);
    estimate.error        = 1.25 * std::abs(d2) / (q - 1.);
    return estimate;
  }

  LinearExtrapolation
  extrapolate_linearly(const std::vector<double> &x,
                       const std::vector<double> &y)
  {
    if (x.size() != y.size() || x.size() < 2)
      throw std::invalid_argument(
        "extrapolate_linearly needs two points or more");
    auto fit = [](const std::vector<double> &xs,
                  const std::vector<double> &ys) {
      const double n  = xs.size();
      double       sx = 0., sy = 0., sxx = 0., sxy = 0.;
      for (unsigned int i = 0; i < xs.size(); ++i)
        {
          sx += xs[i];
          sy += ys[i];
          sxx += xs[i] * xs[i];
          sxy += xs[i] * ys[i];
        }
      const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
      return std::make_pair((sy - slope * sx) / n, slope);
    };
    LinearExtrapolation result;
    std::tie(result.limit, result.slope) = fit(x, y);
    for (unsigned int i = 0; i < x.size(); ++i)
      result.residual =
        std::max(result.residual,
                 std::abs(y[i] - result.limit - result.slope * x[i]));
    result.error = result.residual;
    if (x.size() >= 3)
      {
        const auto coarsest = std::max_element(x.begin(), x.end()) - x.begin();
        std::vector<double> xs, ys;
        for (unsigned int i = 0; i < x.size(); ++i)
          if (static_cast<long>(i) != coarsest)
            {
              xs.push_back(x[i]);
              ys.push_back(y[i]);
            }
        result.error =
          std::max(result.error,
                   3. * std::abs(fit(xs, ys).first - result.limit));
      }
    else
      result.error = std::nan("");
    return result;
  }

} // namespace DiskImpact
