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

  /// Thornton's elastic-plastic contact in LIGGGHTS' form
  /// (Reference::thornton_ning_epsilon()) fitted to a sphere's epsilon(v).
  struct ThorntonFit
  {
    double pressure_ratio = 0.;  ///< the limiting pressure p_y / Y
    double yield_speed    = 0.;  ///< the model's v_y, in the table's units
    std::vector<double> epsilon; ///< the model's, at each speed
    double              max_residual = 0.;
  };

  /// The p_y minimizing sum (eps_model - eps)^2 over the speeds, all alike
  /// (the model's misfit is far larger than the bars), for the yield strain
  /// @p yield_strain = Y / E* and speeds in units of c = sqrt(E* / rho):
  /// a scan over p_y / Y from 0.3 to 30, then Brent's method.
  ThorntonFit
  fit_thornton(const RestitutionTable &table, double yield_strain);

  /// Luding's elastic-plastic contact, Yade's LudingMat
  /// (Reference::luding_epsilon()), fitted to a sphere's epsilon(v).
  struct LudingFit
  {
    double              stiffness_ratio = 0.; ///< kp / k1
    double              plastic_speed   = 0.; ///< v_p, in the table's units
    std::vector<double> epsilon;              ///< the model's, at each speed
    double              max_residual = 0.;
  };

  /// v_p at the table's highest speed (beyond it the model's epsilon rises
  /// again toward 1) and the kp / k1 minimizing sum (eps_model - eps)^2
  /// over the speeds, all alike: a scan over kp / k1 - 1 from 1e-3 to 1e3,
  /// then Brent's method.
  LudingFit
  fit_luding(const RestitutionTable &table);

  /// y(x0) by linear interpolation in log x (clamped to the ends).
  double
  interpolate_in_log(const std::vector<double> &x,
                     const std::vector<double> &y,
                     double                     x0);
} // namespace DiskImpact
