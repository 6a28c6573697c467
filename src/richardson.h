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
   * From the last three values: if the differences shrink monotonically
   * (q = d1 / d2 > 1), the observed order is p = ln q / ln r and the limit
   * f3 + d2 / (q - 1); the order counts as clean if it lies within a
   * factor 2 of @p expected_order, and the error bar is the GCI,
   * 1.25 |d2| / (q - 1). Otherwise (oscillating, growing or an order far from
   * the expected one) there is no extrapolation: the limit is the last
   * value and the error bar 3 max(|d1|, |d2|) / (r^p_expected - 1), with the
   * GCI's safety factor for an unverified order. With two values only the
   * latter applies (with d2).
   */
  RichardsonEstimate
  richardson_estimate(const std::vector<double> &values,
                      double                     ratio,
                      double                     expected_order);
} // namespace DiskImpact
