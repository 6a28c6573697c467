#pragma once

#include <string>
#include <vector>

namespace DiskImpact
{
  /// The sweep's results, in the run's dimensionless units.
  struct RestitutionTable
  {
    std::vector<double> v, epsilon, error, contact_time, delta_max, force_max;
  };

  /// 1 - eps(v) = sum_{k=1}^{K} a_k (v / v_ref)^{k/5}: Hertz's scaling of
  /// the viscoelastic sphere's series (Ramírez et al. 1999), smooth for any
  /// body.
  struct SmoothFit
  {
    double              v_ref = 1.;
    std::vector<double> a;
    double
    operator()(double v) const;
  };

  /// The weight of a point: 1 / its error bar (bars of zero or NaN, i.e.
  /// no error estimate, count as the median bar, or 1).
  std::vector<double>
  fit_weights(const std::vector<double> &error);

  /// Weighted least squares for the a_k of at most @p terms terms (fewer
  /// than the points).
  SmoothFit
  fit_smooth(const RestitutionTable &table, double v_ref, unsigned int terms);

  /// y(x0) by linear interpolation in log x (clamped to the ends).
  double
  interpolate_in_log(const std::vector<double> &x,
                     const std::vector<double> &y,
                     double                     x0);
} // namespace DiskImpact
