#include "contact/complementarity.h"

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// z with W_PP z_P = -q_P on the set P (@p in_set), zero elsewhere.
    Vector<double>
    solve_on_set(const FullMatrix<double> &W,
                 const Vector<double>     &q,
                 const std::vector<bool>  &in_set)
    {
      std::vector<unsigned int> set;
      for (unsigned int i = 0; i < in_set.size(); ++i)
        if (in_set[i])
          set.push_back(i);
      Vector<double> z(q.size());
      if (set.empty())
        return z;
      LAPACKFullMatrix<double> block(set.size(), set.size());
      Vector<double>           rhs(set.size());
      for (unsigned int a = 0; a < set.size(); ++a)
        {
          rhs[a] = -q[set[a]];
          for (unsigned int b = 0; b < set.size(); ++b)
            block(a, b) = W(set[a], set[b]);
        }
      block.compute_cholesky_factorization();
      block.solve(rhs);
      for (unsigned int a = 0; a < set.size(); ++a)
        z[set[a]] = rhs[a];
      return z;
    }

    /// g = q + W mu.
    Vector<double>
    gaps(const FullMatrix<double> &W,
         const Vector<double>     &q,
         const Vector<double>     &mu)
    {
      Vector<double> g(q);
      W.vmult_add(g, mu);
      return g;
    }
  } // namespace

  ComplementaritySolution
  solve_complementarity(const FullMatrix<double> &W,
                        const Vector<double>     &q,
                        const double              tolerance,
                        const std::vector<bool>  &warm_start)
  {
    const unsigned int      n = q.size();
    ComplementaritySolution result;
    result.force.reinit(n);
    // The earlier support: one solve if the contact has not changed.
    if (warm_start.size() == n &&
        std::find(warm_start.begin(), warm_start.end(), true) !=
          warm_start.end())
      {
        const Vector<double> z       = solve_on_set(W, q, warm_start);
        const Vector<double> g       = gaps(W, q, z);
        bool                 optimal = true;
        for (unsigned int i = 0; i < n && optimal; ++i)
          optimal = warm_start[i] ? z[i] > 0. : g[i] >= -tolerance;
        result.iterations = 1;
        if (optimal)
          {
            result.force     = z;
            result.gap       = g;
            result.converged = true;
            return result;
          }
      }
    // Lawson & Hanson from mu = 0: P the forces that may be positive.
    std::vector<bool> in_set(n, false);
    Vector<double>   &mu = result.force;
    for (unsigned int outer = 0; outer < 3 * n + 10; ++outer)
      {
        const Vector<double> g = gaps(W, q, mu);
        // The most penetrating point outside P joins it.
        unsigned int entering = n;
        double       deepest  = -tolerance;
        for (unsigned int i = 0; i < n; ++i)
          if (!in_set[i] && g[i] < deepest)
            {
              deepest  = g[i];
              entering = i;
            }
        if (entering == n)
          {
            result.gap       = g;
            result.converged = true;
            return result;
          }
        in_set[entering] = true;
        // Move toward the solution on P; forces that would turn negative
        // leave P.
        for (unsigned int inner = 0; inner <= n; ++inner)
          {
            ++result.iterations;
            const Vector<double> z = solve_on_set(W, q, in_set);
            // Only rounding can leave the entering force non-positive.
            if (inner == 0 && !(z[entering] > 0.))
              {
                result.gap = gaps(W, q, mu);
                return result;
              }
            double step = 1.;
            for (unsigned int i = 0; i < n; ++i)
              if (in_set[i] && z[i] <= 0.)
                step = std::min(step, mu[i] / (mu[i] - z[i]));
            for (unsigned int i = 0; i < n; ++i)
              mu[i] += step * (z[i] - mu[i]);
            if (step == 1.)
              break;
            for (unsigned int i = 0; i < n; ++i)
              if (in_set[i] && mu[i] <= 0.)
                {
                  in_set[i] = false;
                  mu[i]     = 0.;
                }
          }
      }
    result.gap = gaps(W, q, mu);
    return result;
  }

  Vector<double>
  mean_along_segment(const FullMatrix<double> &W,
                     const Vector<double>     &q0,
                     const Vector<double>     &q1,
                     const double              tolerance)
  {
    const unsigned int n = q0.size();
    Vector<double>     dq(q1), mean(n);
    dq -= q0;
    auto q_at = [&](const double s) {
      Vector<double> q(q0);
      q.add(s, dq);
      return q;
    };
    // Just past s the support is settled: a force that starts at zero
    // there is on it only if it grows.
    auto support_after = [&](const double s) {
      const double      ahead = s + 1e-9 * (1. - s);
      const auto        mu = solve_complementarity(W, q_at(ahead), tolerance);
      std::vector<bool> support(n);
      for (unsigned int i = 0; i < n; ++i)
        support[i] = mu.force[i] > 0.;
      return support;
    };
    double s = 0.;
    for (unsigned int piece = 0; piece < 4 * n + 10 && s < 1.; ++piece)
      {
        const auto support = support_after(s);
        // mu(t) = z0 + t zd on this piece, the gaps g(t) = g0 + t gd.
        const Vector<double> z0 = solve_on_set(W, q0, support);
        const Vector<double> zd = solve_on_set(W, dq, support);
        Vector<double>       g0 = gaps(W, q0, z0), gd(dq);
        W.vmult_add(gd, zd);
        double end = 1.;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double slope = support[i] ? zd[i] : gd[i];
            const double value = support[i] ? z0[i] : g0[i];
            if (slope < 0.)
              {
                const double t = -value / slope;
                if (t > s + 1e-12)
                  end = std::min(end, t);
              }
          }
        // The mean of the linear mu over [s, end].
        mean.add(end - s, z0, (end - s) * 0.5 * (s + end), zd);
        s = end;
      }
    return mean;
  }
} // namespace DiskImpact
