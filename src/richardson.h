#pragma once

#include <vector>

namespace DiskImpact
{
  /// What a sequence of results of ever finer runs says about its limit.
  struct RichardsonEstimate
  {
    double extrapolated = 0.; ///< the estimated limit
    double error        = 0.; ///< error bar of the finest run's value
    double order        = 0.; ///< observed order (NaN if not clean)
    bool   clean        = false;
  };

  /**
   * Richardson extrapolation with Roache's grid convergence index (Roache,
   * J. Fluids Eng. 116, 1994) for results @p values of runs whose
   * parameter (h, dt or 1/k) shrinks by @p ratio from one to the next.
   *
   * From the last three values, with differences d1, d2 and q = d1 / d2:
   *  - q > 1 and the observed order p = ln q / ln r within a factor 2 of
   *    @p expected_order: clean; the limit is f3 + d2 / (q - 1) and the
   *    error bar the GCI, 1.25 |d2| / (q - 1);
   *  - q > 1, p above twice the expected order: no extrapolation, error
   *    3 |d2| / (r^p_expected - 1) (the GCI with its safety factor 3 for an
   *    unverified order);
   *  - q > 1, p below half the expected order: no extrapolation, error
   *    3 |d2| / (q - 1) (the slow observed rate);
   *  - q <= 1 (oscillating or growing): no extrapolation, error
   *    3 max(|d1|, |d2|) / (r^p_expected - 1).
   * With two values only: 3 |d2| / (r^p_expected - 1).
   */
  RichardsonEstimate
  richardson_estimate(const std::vector<double> &values,
                      double                     ratio,
                      double                     expected_order);
} // namespace DiskImpact
