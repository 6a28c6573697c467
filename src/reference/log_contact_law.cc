#include "reference/log_contact_law.h"

#include <boost/math/special_functions/lambert_w.hpp>

#include <cmath>
#include <stdexcept>

namespace DiskImpact
{
  namespace Reference
  {
    LogContactLaw::LogContactLaw(const double constant)
        : c(constant)
    {
    }

    double
    LogContactLaw::constant() const
    {
      return c;
    }

    double
    LogContactLaw::compression(const double load) const
    {
      if (!(load > 0.))
        throw std::invalid_argument("LogContactLaw: the load must be positive");
      return load * (std::log(4. / load) + c);
    }

    double
    LogContactLaw::maximum_compression() const
    {
      return 4. * std::exp(c - 1.);
    }

    double
    LogContactLaw::load(const double compression) const
    {
      if (!(compression > 0.) || !(compression < maximum_compression()))
        throw std::invalid_argument(
          "LogContactLaw: the compression must lie in (0, 4 exp(C - 1))");
      // d = x (ln 4 + C - ln x); with w = ln x - ln 4 - C this is
      // w e^w = -d e^{-C} / 4, and x = -d / w on the branch W_{-1}.
      const double w =
        boost::math::lambert_wm1(-compression * std::exp(-c) / 4.);
      return -compression / w;
    }

    double
    LogContactLaw::constant_from(const double load, const double compression)
    {
      return compression / load - std::log(4. / load);
    }

    double
    hertz_half_width(const double load)
    {
      return 2. * std::sqrt(load);
    }

    double
    centre_of_mass_constant(const double nu2)
    {
      return -2. * std::log(2.) - (1. + nu2) / 4.;
    }

    double
    diameter_constant()
    {
      return -1.;
    }
  } // namespace Reference
} // namespace DiskImpact
