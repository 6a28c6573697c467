#pragma once

#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>

#include <utility>
#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;

  /**
   * The DoFs without inertia (mass redistribution) as what they are at
   * every instant: in equilibrium, K_MM u_M = F_M - K_MI u_I, with the
   * body's other DoFs I held. Gives the contact points' static compliance
   * B K_MM^{-1} B^T and the static response e = K_MM^{-1} B^T mu to point
   * forces mu. K_MM is small (edge DoFs only), replicated on every rank
   * and factorized once.
   */
  template <int dim>
  class MasslessZone
  {
  public:
    /// The massless DoFs of @p op (assembled) must hold the candidates'
    /// DoFs @p candidate_dofs (D of a ContactZone). Collective.
    MasslessZone(
      const ElasticityOperator<dim>                      &op,
      const std::vector<dealii::types::global_dof_index> &candidate_dofs);

    using Row = std::vector<std::pair<unsigned int, double>>;

    /// W(p, q) = b_p^T K_MM^{-1} b_q for the gap rows @p rows (positions
    /// in D).
    dealii::FullMatrix<double>
    compliance(const std::vector<Row> &rows) const;

    /// e = K_MM^{-1} sum_p mu_p b_p (the massless DoFs' static response to
    /// the point forces @p mu, the others held) on D.
    dealii::Vector<double>
    response_on_candidates(const std::vector<Row>       &rows,
                           const dealii::Vector<double> &mu) const;
    /// x += factor e, e as above on M (zero elsewhere).
    void
    add_response(const std::vector<Row>             &rows,
                 const dealii::Vector<double>       &mu,
                 double                              factor,
                 dealii::PETScWrappers::MPI::Vector &x) const;

  private:
    const ElasticityOperator<dim>               &op;
    std::vector<dealii::types::global_dof_index> dofs;    ///< M
    std::vector<unsigned int>                    in_zone; ///< D -> M
    dealii::LAPACKFullMatrix<double>             stiffness;
  };
} // namespace DiskImpact
