#pragma once

#include <boost/math/tools/roots.hpp>

#include <vector>

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * Append to @p roots the roots of @p f in [@p from, @p to): sign changes
     * found on a grid of spacing @p step, each bracketed to machine
     * precision (TOMS 748). Returns the end of the last grid interval, where
     * a later scan continues. The step must lie well below the spacing of
     * the roots, or pairs of roots in one interval go unseen.
     */
    template <typename Function>
    double
    scan_roots(const Function      &f,
               const double         from,
               const double         to,
               const double         step,
               std::vector<double> &roots)
    {
      double x0 = from;
      double f0 = f(x0);
      while (x0 < to)
        {
          const double x1 = x0 + step, f1 = f(x1);
          if (f0 == 0.)
            roots.push_back(x0);
          else if (f0 * f1 < 0.)
            {
              boost::uintmax_t max_iterations = 200;
              const auto       bracket = boost::math::tools::toms748_solve(
                f,
                x0,
                x1,
                f0,
                f1,
                boost::math::tools::eps_tolerance<double>(52),
                max_iterations);
              roots.push_back(0.5 * (bracket.first + bracket.second));
            }
          x0 = x1;
          f0 = f1;
        }
      return x0;
    }
  } // namespace Reference
} // namespace DiskImpact
