#include "contact/contact_law.h"

#include "base/input_error.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace DiskImpact
{
  void
  ContactLaw::stiffen(const double)
  {
  }

  bool
  ContactLaw::approximates_hard_contact() const
  {
    return true;
  }

  double
  ContactLaw::tangential_stiffness() const
  {
    return 0.;
  }

  bool
  ContactLaw::supports_friction() const
  {
    return false;
  }

  double
  ContactLaw::reach() const
  {
    return 0.;
  }

  double
  ContactLaw::discrete_gradient_pressure(const double g0, const double g1) const
  {
    const double dg = g1 - g0;
    // Below this the quotient loses digits; the midpoint pressure is then
    // exact to rounding for a quadratic energy.
    if (std::abs(dg) <= 1e-10 * (std::abs(g0) + std::abs(g1)))
      return pressure(0.5 * (g0 + g1));
    return -(energy(g1) - energy(g0)) / dg;
  }

  double
  ContactLaw::discrete_gradient_derivative(const double g0,
                                           const double g1) const
  {
    const double dg = g1 - g0;
    if (std::abs(dg) <= 1e-10 * (std::abs(g0) + std::abs(g1)))
      return 0.5 * pressure_derivative(0.5 * (g0 + g1));
    // d/dg1 of -(E(g1) - E(g0)) / (g1 - g0), with E'(g) = -p(g)
    return (pressure(g1) * dg + (energy(g1) - energy(g0))) / (dg * dg);
  }

  namespace ContactLaws
  {
    namespace
    {
      /// Filled during static initialization, before main().
      std::map<std::string, Entry> &
      registry()
      {
        static std::map<std::string, Entry> laws;
        return laws;
      }
    } // namespace

    bool
    add(const Entry &entry)
    {
      registry()[entry.name] = entry;
      return true;
    }

    std::vector<Entry>
    all()
    {
      std::vector<Entry> entries;
      for (const auto &[name, entry] : registry())
        entries.push_back(entry);
      return entries;
    }

    std::unique_ptr<ContactLaw>
    create(const std::string &name)
    {
      const auto found = registry().find(name);
      require(found != registry().end(),
              "Contact: there is no law '" + name + "'");
      return found->second.create();
    }
  } // namespace ContactLaws
} // namespace DiskImpact
