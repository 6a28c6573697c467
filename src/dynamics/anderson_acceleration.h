#pragma once

#include <deal.II/lac/vector.h>

#include <vector>

namespace DiskImpact
{
  /**
   * Anderson's acceleration (Walker & Ni, SIAM J. Numer. Anal. 49, 2011) of
   * the fixed-point iteration x <- x + f(x), for small dense problems: the
   * next x combines the last @p depth iterates so that their residuals f
   * cancel best in least squares.
   */
  class AndersonAcceleration
  {
  public:
    explicit AndersonAcceleration(unsigned int depth);

    /// The next iterate after @p x with residual @p f.
    dealii::Vector<double>
    next(const dealii::Vector<double> &x, const dealii::Vector<double> &f);

  private:
    unsigned int                        depth;
    std::vector<dealii::Vector<double>> xs, fs;
  };
} // namespace DiskImpact
