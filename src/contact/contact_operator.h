#pragma once

#include "contact/contact.h"

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <utility>
#include <vector>

namespace DiskImpact
{
  class ElasticityOperator;

  /// How the contact force of a time step is formed from the gaps at its
  /// start (g0) and end (g1).
  enum class ContactAverage
  {
    trapezoidal,      ///< (1 - w) p(g0) + w p(g1): Newmark, generalized-alpha
    discrete_gradient ///< -(E(g1) - E(g0)) / (g1 - g0): conserves energy
  };

  /**
   * A rank-one part w (b . u)(b . v) of the contact tangent, b given by its
   * entries on unconstrained DoFs (constraints already resolved).
   */
  struct RankOneTerm
  {
    double                                                          weight = 0.;
    std::vector<std::pair<dealii::types::global_dof_index, double>> entries;
  };

  /// Integrals of the wall's pressure over the disk's edge.
  struct ContactState
  {
    /// int p ds: the wall's force on the disk along its normal.
    double force = 0.;
    /// int p_bar ds: the force averaged over a time step (assemble_step).
    double force_average = 0.;
    /// int (the law's energy) ds.
    double energy = 0.;
    /// max(-g): the deepest penetration.
    double max_penetration = 0.;
    /// int p t^2 ds, t the coordinate of the undeformed edge point along the
    /// wall, from the point of the wall nearest the disk's centre.
    double second_moment = 0.;

    /// Half-width of a Hertz profile p0 sqrt(1 - t^2/a^2) with the same
    /// zeroth and second moments: a = 2 sqrt(second_moment / force).
    double
    half_width() const;
  };

  /**
   * The contact (WallLaw) of the disk's curved edge with a rigid wall, on the
   * quadrature points of the edge faces: the residual contribution
   * -int p (n . v) ds and its consistent tangent -int p'(g) (n . u)(n . v) ds
   * (p' = -k H(-g) for the penalty, H the Heaviside function), for small
   * strains (reference edge, current gap).
   */
  class ContactOperator
  {
  public:
    ContactOperator(const ElasticityOperator &op,
                    const RigidWall          &wall,
                    const WallLaw            &law,
                    const dealii::Point<2>   &disk_center);

    /**
     * Add the contact terms at the displacement @p ghosted_u to @p residual
     * (if not null) and @p tangent (if not null; the caller compresses both)
     * and return the integrals, summed over all ranks.
     */
    ContactState
    assemble(const dealii::PETScWrappers::MPI::Vector &ghosted_u,
             dealii::PETScWrappers::MPI::Vector       *residual,
             dealii::PETScWrappers::MPI::SparseMatrix *tangent) const;

    /**
     * The contact force of a time step from @p ghosted_u_old to
     * @p ghosted_u_new, averaged as @p average (with the weight
     * @p new_weight of the new state if trapezoidal): its residual
     * contribution is
     * added to @p residual (the caller compresses), the tangent with respect
     * to the new state is returned as rank-one terms in @p tangent_terms
     * (locally owned faces only). The returned state is that of the new
     * displacement, with force_average the averaged force.
     */
    ContactState
    assemble_step(const dealii::PETScWrappers::MPI::Vector &ghosted_u_old,
                  const dealii::PETScWrappers::MPI::Vector &ghosted_u_new,
                  ContactAverage                            average,
                  double                                    new_weight,
                  dealii::PETScWrappers::MPI::Vector       &residual,
                  std::vector<RankOneTerm> *tangent_terms) const;

    /// (t, p) at the quadrature points with p > 0, on all ranks, sorted by t.
    std::vector<std::pair<double, double>>
    pressure_profile(const dealii::PETScWrappers::MPI::Vector &ghosted_u) const;

    /// The length of the smallest face on the curved edge (over all ranks).
    static double
    smallest_edge_face(const ElasticityOperator &op);

  private:
    const ElasticityOperator &op;
    RigidWall                 wall;
    WallLaw                   law;
    /// Where t = 0: the point of the wall nearest the disk's centre.
    dealii::Point<2>     origin;
    dealii::Tensor<1, 2> tangent_direction;
    /// The smallest undeformed gap of each locally owned edge face, in the
    /// order of for_each_curved_edge_face().
    std::vector<double> face_gap;
  };
} // namespace DiskImpact
