#pragma once

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * The quasistatic contact law of a 2D disk on a rigid wall (Gerl &
     * Zippelius 1999, eq. 57; Schwager 2007, eqs. 2-3) in dimensionless form:
     * with the load x = P / (pi E2 R) and the compression d = delta / R,
     *
     *   d = x [ln(4 / x) + C],
     *
     * (equivalently delta = P/(pi E2) [ln(4 pi R E2 / P) + C]); Gerl &
     * Zippelius print C = -1 - nu2. The constant depends on which compression
     * is meant and on how the load is applied
     * (docs/theory/disk-contact-constants.md).
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
       * x < 4 e^{C-1}) through the Lambert W function (Schwager 2007, eq. 3):
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

    /// Hertz half-width a / R = 2 sqrt(x) of the contact zone (Gerl & Zippelius
    /// 1999, eq. 48: a^2 = 4 P R / (pi E2)).
    double
    hertz_half_width(double load);

    /**
     * The constant C of the law for the approach of the centre of mass
     * (the area mean of the displacement) of a disk pressed on the rigid
     * wall by a uniform body force, derived from Michell's stress field
     * (Gerl & Zippelius 1999, eqs. 50-53) with Hertz's contact (eq. 46):
     *
     *   C_com = -2 ln 2 - (1 + nu2) / 4,
     *
     * i.e. delta_com = P/(pi E2) [ln(pi R E2 / P) - (1 + nu2)/4]
     * (docs/theory/disk-contact-constants.md). @p nu2 is the in-plane
     * Poisson ratio.
     */
    double
    centre_of_mass_constant(double nu2);

    /// The constant C of the shortening of the diameter on the impact axis,
    /// -1 for every Poisson ratio (docs/theory/disk-contact-constants.md;
    /// Gerl & Zippelius 1999, eq. 57 prints -1 - nu2).
    double
    diameter_constant();
  } // namespace Reference
} // namespace DiskImpact
