#pragma once

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * The quasistatic contact law of a 2D disk on a rigid wall (seed 001,
     * eq. 57; seed 000, eqs. 2-3) in dimensionless form: with the load
     * x = P / (pi E2 R) and the compression d = delta / R,
     *
     *   d = x [ln(4 / x) + C],
     *
     * (equivalently delta = P/(pi E2) [ln(4 pi R E2 / P) + C]); the seed
     * prints C = -1 - nu2. The constant depends on which compression is
     * meant and on how the load is applied (docs/contact-law.md).
     */
    class LogContactLaw
    {
    public:
      explicit LogContactLaw(double constant);

      double
      constant() const;

      /// d(x) for a load x > 0.
      double
      compression(double load) const;

      /**
       * The inverse x(d) on the physical branch (d increasing with x,
       * x < 4 e^{C-1}) through the Lambert W function (seed 000, eq. 3):
       * x = -d / W_{-1}(-d e^{-C} / 4). Needs 0 < d < 4 e^{C-1}.
       */
      double
      load(double compression) const;

      /// The largest compression on the physical branch, 4 e^{C-1}.
      double
      maximum_compression() const;

      /// The constant C that makes the law pass through (x, d).
      static double
      constant_from(double load, double compression);

    private:
      double c;
    };

    /// Hertz half-width a / R = 2 sqrt(x) of the contact zone (seed 001,
    /// eq. 48: a^2 = 4 P R / (pi E2)).
    double
    hertz_half_width(double load);
  } // namespace Reference
} // namespace DiskImpact
