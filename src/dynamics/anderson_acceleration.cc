#include "dynamics/anderson_acceleration.h"

#include <deal.II/lac/lapack_full_matrix.h>

namespace DiskImpact
{
  using namespace dealii;

  template <typename VectorType>
  AndersonAcceleration<VectorType>::AndersonAcceleration(
    const unsigned int depth)
      : depth(depth)
  {
  }

  template <typename VectorType>
  VectorType
  AndersonAcceleration<VectorType>::next(const VectorType &x,
                                         const VectorType &f)
  {
    if (last_x.size() > 0 && depth > 0)
      {
        // The newest differences, and their row of the Gram matrix.
        if (dF.size() == depth)
          {
            dX.erase(dX.begin());
            dF.erase(dF.begin());
            gram.erase(gram.begin());
            for (auto &row : gram)
              row.erase(row.begin());
          }
        dX.push_back(x);
        dX.back() -= last_x;
        dF.push_back(f);
        dF.back() -= last_f;
        std::vector<double> row(dF.size());
        for (unsigned int j = 0; j < dF.size(); ++j)
          row[j] = dF.back() * dF[j];
        for (unsigned int j = 0; j + 1 < dF.size(); ++j)
          gram[j].push_back(row[j]);
        gram.push_back(row);
      }
    last_x = x;
    last_f = f;
    VectorType result(x);
    result += f;
    const unsigned int m = dF.size();
    if (m == 0)
      return result;
    // gamma minimizes |f - dF gamma| by the normal equations (m <= depth
    // is small), slightly regularized.
    LAPACKFullMatrix<double> normal(m, m);
    Vector<double>           gamma(m);
    double                   trace = 0.;
    for (unsigned int i = 0; i < m; ++i)
      {
        gamma[i] = dF[i] * f;
        for (unsigned int j = 0; j < m; ++j)
          normal(i, j) = gram[i][j];
        trace += normal(i, i);
      }
    if (!(trace > 0.))
      return result;
    for (unsigned int i = 0; i < m; ++i)
      normal(i, i) += 1e-12 * trace;
    normal.compute_lu_factorization();
    normal.solve(gamma);
    for (unsigned int j = 0; j < m; ++j)
      {
        result.add(-gamma[j], dX[j]);
        result.add(-gamma[j], dF[j]);
      }
    return result;
  }

  template class AndersonAcceleration<Vector<double>>;
  template class AndersonAcceleration<PETScWrappers::MPI::Vector>;
} // namespace DiskImpact
