#pragma once

#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace DiskImpact
{
  /**
   * Anderson's acceleration (Walker & Ni, SIAM J. Numer. Anal. 49, 2011) of
   * the fixed-point iteration x <- x + f(x): the next x combines the last
   * @p depth iterates so that their residuals f cancel best in least
   * squares. VectorType: a serial dealii::Vector for small dense problems,
   * or a distributed PETSc vector (its inner products are global, so every
   * rank takes the same combination). It keeps the differences of the
   * last iterates and residuals and their residuals' inner products, so a
   * step costs 2 depth + 1 inner products.
   */
  template <typename VectorType = dealii::Vector<double>>
  class AndersonAcceleration
  {
  public:
    explicit AndersonAcceleration(unsigned int depth);

    /// The next iterate after @p x with residual @p f.
    VectorType
    next(const VectorType &x, const VectorType &f);

  private:
    unsigned int depth;
    /// The last iterate and residual, and the differences of consecutive
    /// ones (oldest first), with gram(i, j) = dF_i . dF_j.
    VectorType                       last_x, last_f;
    std::vector<VectorType>          dX, dF;
    std::vector<std::vector<double>> gram;
  };

  extern template class AndersonAcceleration<dealii::Vector<double>>;
  extern template class AndersonAcceleration<
    dealii::PETScWrappers::MPI::Vector>;
} // namespace DiskImpact
