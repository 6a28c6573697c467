#include "dynamics/richardson.h"

#include "base/input_error.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace DiskImpact
{
  namespace
  {
    /// The observed order of the triple ending at values[end], NaN unless
    /// it converges monotonically (q = d1 / d2 > 1).
    double
    triple_order(const std::vector<double> &values,
                 const std::size_t          end,
                 const double               ratio)
    {
      const double d1 = values[end - 1] - values[end - 2];
      const double d2 = values[end] - values[end - 1];
      const double q  = d1 / d2;
      return d2 != 0. && q > 1. ? std::log(q) / std::log(ratio) :
                                  std::numeric_limits<double>::quiet_NaN();
    }

    /// Largest distance of the last three triples' orders from their mean
    /// (NaN unless there are three monotone triples).
    double
    order_scatter(const std::vector<double> &values, const double ratio)
    {
      const std::size_t n = values.size();
      if (n < 5)
        return std::numeric_limits<double>::quiet_NaN();
      std::vector<double> orders;
      for (std::size_t end = n - 3; end < n; ++end)
        orders.push_back(triple_order(values, end, ratio));
      const double mean    = (orders[0] + orders[1] + orders[2]) / 3.;
      double       scatter = 0.;
      for (const double p : orders)
        scatter = std::max(scatter, std::abs(p - mean));
      return std::isnan(mean) ? mean : scatter;
    }

    /// Why a sequence of @p n values with last differences @p d1, @p d2,
    /// whose last triple has the observed @p order and whose last three
    /// triples scatter by @p scatter, is not clean.
    std::string
    not_clean_because(const std::size_t n,
                      const double      d1,
                      const double      d2,
                      const double      order,
                      const double      scatter,
                      const double      expected_order)
    {
      std::ostringstream why;
      why << std::setprecision(2);
      if (n >= 3 && d1 * d2 < 0.)
        why << std::scientific << "the last two differences change sign (" << d1
            << ", " << d2 << ")";
      else if (n >= 3 && !(std::abs(d2) < std::abs(d1)))
        why << std::scientific << "the last difference (" << d2
            << ") is not smaller than the one before (" << d1 << ")";
      else if (n < 5)
        why << n << " levels; a verified order needs 5 (three level triples)";
      else if (std::isnan(scatter))
        why << "an earlier triple of the last five levels does not converge "
               "monotonically";
      else if (scatter > clean_order_scatter)
        why << std::fixed << "the orders of the last three triples scatter by "
            << scatter << " > " << clean_order_scatter;
      else
        why << std::fixed << "the observed order " << order
            << " is not within a factor 2 of the expected " << expected_order;
      return why.str();
    }
  } // namespace

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
    estimate.extrapolated  = values[n - 1];
    estimate.order         = std::numeric_limits<double>::quiet_NaN();
    estimate.order_scatter = order_scatter(values, ratio);
    const double d1        = n < 3 ? 0. : values[n - 2] - values[n - 3];
    estimate.error         = 3. * std::max(std::abs(d1), std::abs(d2)) /
                     (std::pow(ratio, expected_order) - 1.);
    const double q             = n < 3 || d2 == 0. ? 0. : d1 / d2;
    const double order         = q > 1. ? std::log(q) / std::log(ratio) :
                                          std::numeric_limits<double>::quiet_NaN();
    estimate.not_clean_because = not_clean_because(
      n, d1, d2, order, estimate.order_scatter, expected_order);
    if (!(q > 1.))
      return estimate;
    // Monotone convergence: the last difference alone bounds the rest.
    if (order > 2. * expected_order)
      {
        estimate.error =
          3. * std::abs(d2) / (std::pow(ratio, expected_order) - 1.);
        return estimate;
      }
    estimate.error = 3. * std::abs(d2) / (q - 1.);
    if (order < 0.5 * expected_order ||
        !(estimate.order_scatter <= clean_order_scatter))
      return estimate;
    estimate.clean             = true;
    estimate.not_clean_because = "";
    estimate.order             = order;
    estimate.extrapolated      = values[n - 1] + d2 / (q - 1.);
    estimate.error             = 1.25 * std::abs(d2) / (q - 1.);
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
