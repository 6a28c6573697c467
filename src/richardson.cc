#include "richardson.h"

#include "input_error.h"

#include <cmath>
#include <limits>

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
} // namespace DiskImpact
