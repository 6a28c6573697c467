#pragma once

#include <string>
#include <vector>

namespace DiskImpact
{
  /// What a sequence of results of ever finer runs says about its limit.
  struct RichardsonEstimate
  {
    double extrapolated = 0.; ///< the estimated limit
    double error        = 0.; ///< error bar of the finest run's value
    double order        = 0.; ///< observed order (NaN if not clean)
    /// Largest distance of a triple's order from the mean of the last
    /// three triples' orders (NaN with fewer than five values or a
    /// non-monotone sequence).
    double order_scatter = 0.;
    bool   clean         = false;
    /// Why the sequence was not extrapolated, in a few words (empty if
    /// it was clean).
    std::string not_clean_because;
  };

  /// How far the observed orders of the last three triples may lie from
  /// their mean for a sequence to count as clean.
  constexpr double clean_order_scatter = 0.25;

  /**
   * Richardson extrapolation with Roache's grid convergence index (Roache,
   * J. Fluids Eng. 116, 1994) for results @p values of runs whose
   * parameter (h, dt or 1/k) shrinks by @p ratio from one to the next.
   *
   * The observed order of a triple of successive values with differences
   * d1, d2 and q = d1 / d2 > 1 is p = ln q / ln r. From the last three
   * values:
   *  - clean only if the orders of the last three triples (five values)
   *    all lie within clean_order_scatter of their mean and that mean
   *    within a factor 2 of @p expected_order: the limit is
   *    f_n + d2 / (q - 1) and the error bar the GCI, 1.25 |d2| / (q - 1);
   *  - q > 1, p within a factor 2 of the expected order but not verified
   *    by three triples (fewer values, or scattered orders): no
   *    extrapolation, error 3 |d2| / (q - 1) (the GCI with its safety
   *    factor 3 for an unverified order);
   *  - q > 1, p above twice the expected order: no extrapolation, error
   *    3 |d2| / (r^p_expected - 1);
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

  /// A straight-line least-squares fit y = limit + slope x, with what it
  /// says about the extrapolation to x = 0.
  struct LinearExtrapolation
  {
    double limit    = 0.; ///< y at x = 0
    double slope    = 0.;
    double residual = 0.; ///< largest |y_i - fit(x_i)|
    /// max(3 |limit - limit without the point of largest x|, residual):
    /// how far the limit moves if the coarsest point is dropped, with the
    /// safety factor 3 of richardson_estimate()'s fallbacks, at least the
    /// misfit; NaN for two points (a line through them says nothing).
    double error = 0.;
  };

  /// Fit y = limit + slope x to (@p x, @p y) (at least two points).
  LinearExtrapolation
  extrapolate_linearly(const std::vector<double> &x,
                       const std::vector<double> &y);

} // namespace DiskImpact
