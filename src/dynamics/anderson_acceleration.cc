#include "dynamics/anderson_acceleration.h"

#include <deal.II/lac/lapack_full_matrix.h>

namespace DiskImpact
{
  using namespace dealii;

  AndersonAcceleration::AndersonAcceleration(const unsigned int depth)
      : depth(depth)
  {
  }

  Vector<double>
  AndersonAcceleration::next(const Vector<double> &x, const Vector<double> &f)
  {
    xs.push_back(x);
    fs.push_back(f);
    if (xs.size() > depth + 1)
      {
        xs.erase(xs.begin());
        fs.erase(fs.begin());
      }
    const unsigned int m = xs.size() - 1;
    Vector<double>     result(x);
    result += f;
    if (m == 0)
      return result;
    // gamma minimizes |f - dF gamma|, dF_j = f_{j+1} - f_j, by the normal
    // equations (m <= depth is small), slightly regularized.
    std::vector<Vector<double>> dF(m), dX(m);
    for (unsigned int j = 0; j < m; ++j)
      {
        dF[j] = fs[j + 1];
        dF[j] -= fs[j];
        dX[j] = xs[j + 1];
        dX[j] -= xs[j];
      }
    LAPACKFullMatrix<double> normal(m, m);
    Vector<double>           gamma(m);
    double                   trace = 0.;
    for (unsigned int i = 0; i < m; ++i)
      {
        gamma[i] = dF[i] * f;
        for (unsigned int j = 0; j < m; ++j)
          normal(i, j) = dF[i] * dF[j];
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
} // namespace DiskImpact
