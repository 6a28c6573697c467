#include "dynamics/massless_zone.h"

#include "base/run_error.h"
#include "elasticity/elasticity_operator.h"

#include <algorithm>

namespace DiskImpact
{
  using namespace dealii;

  template <int dim>
  MasslessZone<dim>::MasslessZone(
    const ElasticityOperator<dim>              &op,
    const std::vector<types::global_dof_index> &candidate_dofs)
      : op(op)
      , dofs(op.massless_dof_list())
  {
    for (const auto dof : candidate_dofs)
      {
        const auto at = std::lower_bound(dofs.begin(), dofs.end(), dof);
        if (at == dofs.end() || *at != dof)
          throw RunError("a contact candidate's DoF carries mass: the "
                         "massless zone does not cover the contact zone");
        in_zone.push_back(at - dofs.begin());
      }
    stiffness.reinit(dofs.size());
    stiffness = op.stiffness_block(dofs);
    stiffness.compute_cholesky_factorization();
  }

  namespace
  {
    /// K_MM^{-1} sum_p mu_p b_p on M.
    Vector<double>
    solve_static(
      const LAPACKFullMatrix<double>  &stiffness,
      const std::vector<unsigned int> &in_zone,
      const std::vector<std::vector<std::pair<unsigned int, double>>> &rows,
      const Vector<double>                                            &mu,
      const unsigned int                                               n)
    {
      Vector<double> x(n);
      for (unsigned int p = 0; p < rows.size(); ++p)
        if (mu[p] != 0.)
          for (const auto &[i, b] : rows[p])
            x[in_zone[i]] += mu[p] * b;
      stiffness.solve(x);
      return x;
    }
  } // namespace

  template <int dim>
  FullMatrix<double>
  MasslessZone<dim>::compliance(const std::vector<Row> &rows) const
  {
    const unsigned int n = rows.size();
    FullMatrix<double> W(n, n);
    for (unsigned int q = 0; q < n; ++q)
      {
        Vector<double> unit(n);
        unit[q] = 1.;
        const Vector<double> x =
          solve_static(stiffness, in_zone, rows, unit, dofs.size());
        for (unsigned int p = 0; p < n; ++p)
          for (const auto &[i, b] : rows[p])
            W(p, q) += b * x[in_zone[i]];
      }
    return W;
  }

  template <int dim>
  Vector<double>
  MasslessZone<dim>::response_on_candidates(const std::vector<Row> &rows,
                                            const Vector<double>   &mu) const
  {
    const Vector<double> x =
      solve_static(stiffness, in_zone, rows, mu, dofs.size());
    Vector<double> on_candidates(in_zone.size());
    for (unsigned int i = 0; i < in_zone.size(); ++i)
      on_candidates[i] = x[in_zone[i]];
    return on_candidates;
  }

  template <int dim>
  void
  MasslessZone<dim>::add_response(const std::vector<Row>     &rows,
                                  const Vector<double>       &mu,
                                  const double                factor,
                                  PETScWrappers::MPI::Vector &x) const
  {
    const Vector<double> e =
      solve_static(stiffness, in_zone, rows, mu, dofs.size());
    for (unsigned int m = 0; m < dofs.size(); ++m)
      if (op.locally_owned_dofs().is_element(dofs[m]))
        x(dofs[m]) += factor * e[m];
    x.compress(VectorOperation::add);
  }

  template class MasslessZone<2>;
  template class MasslessZone<3>;
} // namespace DiskImpact
