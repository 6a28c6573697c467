#pragma once

#include <string>
#include <utility>
#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /// Kinds of free-body modes (disk: Gerl & Zippelius 1999, section 2.2;
    /// sphere: Lamb).
    enum class ModeFamily
    {
      rigid,     ///< omega = 0: translations and the rotation
      radial,    ///< n = 0, u_phi = 0 (breathing modes)
      torsional, ///< n = 0, u_r = 0 (disk)
      mixed,     ///< disk, n >= 1: radial and tangential motion coupled
      spheroidal ///< sphere, n >= 1: u_r ~ P_n(cos theta), coupled u_theta
    };

    std::string
    to_string(ModeFamily family);

    /// (n, l, family): angular order, root index (from 0), family.
    struct ModeLabel
    {
      unsigned int n      = 0;
      unsigned int l      = 0;
      ModeFamily   family = ModeFamily::mixed;

      bool
      operator==(const ModeLabel &other) const;
      bool
      operator<(const ModeLabel &other) const;
    };

    /// The labels of the @p n_modes lowest of the (kappa, label) pairs
    /// @p found, in ascending kappa (equal kappa in their given order).
    std::vector<ModeLabel>
    lowest_labels(std::vector<std::pair<double, ModeLabel>> found,
                  unsigned int                              n_modes);

    /// The analytic eigenfrequencies of a free elastic body.
    class FreeBodyModes
    {
    public:
      virtual ~FreeBodyModes() = default;

      /// Angular frequency of mode (n, l, family); 0 for rigid modes.
      virtual double
      omega(const ModeLabel &mode) const = 0;

      /**
       * The lowest @p n_modes elastic modes in ascending frequency, with
       * their multiplicity on the domain (@p half_domain: only the modes
       * symmetric about the impact axis).
       */
      virtual std::vector<ModeLabel>
      lowest_modes(unsigned int n_modes, bool half_domain) const = 0;
    };
  } // namespace Reference
} // namespace DiskImpact
