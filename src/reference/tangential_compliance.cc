#include "reference/tangential_compliance.h"

#include "reference/log_contact_law.h"

#include <cmath>

namespace DiskImpact::Reference
{
  namespace
  {
    /// Mindlin (1949) for one elastic sphere on a rigid flat:
    /// delta_t = 3 mu P (2 - nu) / (16 G a) [1 - (1 - q)^(2/3)],
    /// G = E* (1 - nu) / 2; the stick radius c = a (1 - q)^(1/3).
    class MindlinSphere : public TangentialCompliance
    {
    public:
      double
      displacement(const double q,
                   const double friction_load,
                   const double a,
                   const double nu) const override
      {
        return 3. * (2. - nu) / (8. * (1. - nu)) * friction_load / a *
               (1. - std::pow(1. - q, 2. / 3.));
      }

      double
      stick_radius(const double q) const override
      {
        return std::cbrt(1. - q);
      }
    };

    /// Cattaneo's disk: the traction mu p_Hertz(a) - mu (c/a)^2
    /// p_Hertz(c), c = a sqrt(1 - q), and the disk's response to a
    /// Hertz-shaped tangential traction of total T and half-width b: its
    /// rigid motion at the contact point moves by
    /// (T / (pi E2)) [2 ln(4R / b) + C_I].
    class CattaneoDisk : public TangentialCompliance
    {
    public:
      double
      displacement(const double q,
                   const double friction_load,
                   const double a,
                   const double nu) const override
      {
        return friction_load / M_PI *
               (q * (2. * std::log(4. / a) + cattaneo_constant(nu)) +
                (1. - q) * std::log(1. - q));
      }

      double
      stick_radius(const double q) const override
      {
        return std::sqrt(1. - q);
      }
    };
  } // namespace

  double
  cattaneo_constant(const double nu2)
  {
    return 1. / 12. + 13. * nu2 / 12. - 2. * std::log(2.);
  }

  double
  disk_tangential_stiffness_ratio(const double a, const double nu2)
  {
    const double log_term = 2. * std::log(4. / a) - 1.;
    return (log_term + centre_of_mass_constant(nu2)) /
           (log_term + cattaneo_constant(nu2));
  }

  std::unique_ptr<TangentialCompliance>
  tangential_compliance(const bool sphere)
  {
    if (sphere)
      return std::make_unique<MindlinSphere>();
    return std::make_unique<CattaneoDisk>();
  }
} // namespace DiskImpact::Reference
