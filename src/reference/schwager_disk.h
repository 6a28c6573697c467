#pragma once

#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * The coefficients c_k, k = 0 ... @p n - 1, of the first-order
     * restitution series (Schwager 2007, eq. 48):
     *
     *   c_k = a_k int_0^1 dy sqrt(1 - y^2) [2 y^2 ln y / (1 - y^2)]^k,
     *
     * a_k the Taylor coefficients of sqrt(1 + z) about z = 0. The integrals
     * are evaluated by tanh-sinh quadrature in y = sin(theta).
     */
    std::vector<double>
    schwager_c_coefficients(unsigned int n);

    /// c_0 = pi / 4 in closed form.
    double
    schwager_c0_closed_form();

    /**
     * c_1 = pi (1 - ln 4) / 8 in closed form: with y = sin(theta),
     * c_1 = int_0^{pi/2} sin^2(theta) ln sin(theta) d theta.
     */
    double
    schwager_c1_closed_form();

    /**
     * The coefficients d_k of the second-order term (Schwager 2007, eqs.
     * 78-79), one for each c_k:
     *
     *   d_0 = -c_0^2,
     *   d_k = -2 sum_{i<k} (k - i - 1) c_i c_{k-i-1} - sum_{i<=k} c_i c_{k-i}.
     */
    std::vector<double>
    schwager_d_coefficients(const std::vector<double> &c);

    /**
     * The largest scaled impact velocity for which the elastic law
     * x = -F ln F (Schwager 2007, eq. 18) can stop the disk: the largest
     * potential energy is reached at F = 1/e, where -2 e v^2 = -1/e (eq. 50),
     * so v_max = 1 / (sqrt(2) e).
     */
    double
    schwager_maximum_scaled_velocity();

    /**
     * The scaled impact velocity v = (g / c) e^{-C} / 4 (Schwager 2007, eq. 12)
     * of a disk hitting a rigid wall at speed g, for the log law
     * delta / R = x_P [ln(4 / x_P) + C], x_P = P / (pi E2 R), and the mass
     * m = rho pi R^2; @p impact_speed_over_wave_speed is g / c,
     * c = sqrt(E2 / rho). The scaled variables are x = e^{-C} delta / (4 R),
     * F = e^{-C} P / (4 pi E2 R) and tau = t c / R.
     */
    double
    schwager_scaled_velocity(double impact_speed_over_wave_speed,
                             double constant);

    /// The scaled damping alpha = A c / R (Schwager 2007, eq. 13), A the
    /// Kelvin-Voigt relaxation time.
    double
    schwager_scaled_damping(double relaxation_time,
                            double wave_speed,
                            double radius);

    /**
     * u = -W_{-1}(-2 e v^2) >= 1, the variable of the restitution series
     * (Schwager 2007, eqs. 50, 56). Schwager's "W_0" is the branch W <= -1,
     * W_{-1} in the usual notation, since 1 + 2 ln F_max = W and the
     * physical branch of eq. 18 has F < 1/e. Throws std::domain_error
     * unless 0 < v <= v_max.
     */
    double
    schwager_series_variable(double scaled_velocity);

    /**
     * The coefficient of restitution of the viscoelastic disk
     * x'' + F(x) + alpha x' F'(x) = 0, x = -F ln F (Schwager 2007, eqs. 14,
     * 18), as the power series epsilon = 1 + alpha f_1(v) + alpha^2 f_2(v) +
     * ... (eq. 62). The collision ends when the overlap x returns to zero: the
     * energy balance (eq. 21) and the time reversal (eqs. 63-67) both assume
     * it. The force criterion ends it earlier, with an epsilon larger by
     * O(alpha^2) (end_criterion_difference()).
     */
    class SchwagerDiskRestitution
    {
    public:
      /// Holds c_0 ... c_{n-1} (quadrature) and d_0 ... d_{n-1}.
      explicit SchwagerDiskRestitution(unsigned int n_coefficients = 16);

      const std::vector<double> &
      c_coefficients() const;

      const std::vector<double> &
      d_coefficients() const;

      /// f_1(v) = -sqrt(8) sum_k c_k u^{-k-1/2}, u = -W_{-1}(-2 e v^2)
      /// (Schwager 2007, eq. 72); 0 < v <= v_max.
      double
      first_order_term(double scaled_velocity) const;

      /**
       * f_2(v) = 4 / (1 - u) sum_k d_k u^{-k} (Schwager 2007, eq. 77 with
       * 1 + W = 1 - u < 0), which equals (f_1^2 + v f_1 f_1') / 2 (eq. 71);
       * 0 < v < v_max (f_2 diverges at v_max).
       */
      double
      second_order_term(double scaled_velocity) const;

      /// epsilon = 1 + alpha f_1(v), error O(alpha^2) (Schwager 2007, eq. 56).
      double
      first_order(double alpha, double scaled_velocity) const;

      /// epsilon = 1 + alpha f_1(v) + alpha^2 f_2(v), error O(alpha^3)
      /// (Schwager 2007, eq. 80).
      double
      second_order(double alpha, double scaled_velocity) const;

      /**
       * The first-order epsilon = 1 + Delta E / v^2 with the energy loss of
       * eq. 41 integrated as it stands, without the series of eqs. 45-47:
       *
       *   epsilon = 1 - 2 alpha sqrt(2 / u)
       *                 int_0^1 dy sqrt(1 - y^2 + 2 y^2 ln y / u).
       *
       * It differs from first_order() only by the truncation of the series.
       */
      static double
      first_order_unexpanded(double alpha, double scaled_velocity);

      /**
       * epsilon_force - epsilon_overlap = alpha^2 (-1 - 2 s) / (4 s^2)
       * + O(alpha^3), s = W_{-1}(-e alpha v): the difference between a
       * collision ending when the total force F + alpha x' F' returns to
       * zero (Schwager & Pöschel 2007, eq. 17) and one ending when the overlap
       * does. The force vanishes at F(1 + ln F) = -alpha w, w = |x'| = v +
       * O(alpha), i.e. 1 + ln F = s; from there to x = 0 the total force is
       * attractive and takes the kinetic energy alpha w F - Phi(F)
       * = -alpha^2 w^2 (1 + 2 s) / (4 s^2) (eq. 36 for Phi). Needs
       * alpha v <= e^{-2}.
       */
      static double
      end_criterion_difference(double alpha, double scaled_velocity);

      /// second_order() plus end_criterion_difference(): epsilon to
      /// O(alpha^3) for a collision that ends when the force vanishes.
      double
      second_order_force_criterion(double alpha, double scaled_velocity) const;

    private:
      std::vector<double> c;
      std::vector<double> d;
    };
  } // namespace Reference
} // namespace DiskImpact
