#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace DiskImpact
{
  /**
   * The linear complementarity problem of frictionless contact with
   * non-penetration imposed exactly: find the point forces mu with
   *
   *   g = q + W mu >= 0,   mu >= 0,   mu_i g_i = 0,
   *
   * for a symmetric positive definite W (the gaps' response to the
   * forces): the optimality conditions of min 1/2 mu^T W mu + q^T mu over
   * mu >= 0. Solved by the active-set method of Lawson & Hanson (Solving
   * Least Squares Problems, 1974, ch. 23) for this quadratic, which ends
   * after finitely many steps; @p warm_start, the support of an earlier
   * solution, is tried first and kept if it satisfies the conditions.
   */
  struct ComplementaritySolution
  {
    dealii::Vector<double> force; ///< mu
    dealii::Vector<double> gap;   ///< g = q + W mu
    unsigned int           iterations = 0;
    bool                   converged  = false;
  };

  /// @p tolerance: the gap below zero accepted where mu = 0 (and the
  /// rounding of g where mu > 0).
  ComplementaritySolution
  solve_complementarity(const dealii::FullMatrix<double> &W,
                        const dealii::Vector<double>     &q,
                        double                            tolerance,
                        const std::vector<bool>          &warm_start = {});
  /**
   * The mean over s in [0, 1] of the solution mu(s) of the problem with
   * q(s) = (1 - s) @p q0 + s @p q1 and W fixed. mu(s) is piecewise linear
   * in s: on each piece mu = -W_PP^{-1} q_P(s) on its support P, and a
   * piece ends where a force falls to zero or a gap closes. The mean is
   * summed piece by piece, exact to rounding.
   */
  dealii::Vector<double>
  mean_along_segment(const dealii::FullMatrix<double> &W,
                     const dealii::Vector<double>     &q0,
                     const dealii::Vector<double>     &q1,
                     double                            tolerance);
} // namespace DiskImpact
