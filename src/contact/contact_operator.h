#pragma once

#include "contact/contact.h"

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <array>
#include <utility>
#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;

  /// Integrals of the wall's pressure over the body's boundary (dS = ds
  /// for a disk, 2 pi r ds for a sphere's meridian, the surface's dS in
  /// 3D).
  struct ContactState
  {
    /// Whether the contact is a circle (a sphere; its pressure is Hertz's
    /// of a circle).
    bool axisymmetric = false;
    /// int p dS: the wall's force on the body along its normal.
    double force = 0.;
    /// int p_bar ds: the force averaged over a time step (ContactZone).
    double force_average = 0.;
    /// int (the law's energy) ds, with the elastic energy of the stick
    /// under friction.
    double energy = 0.;
    /// int tau_bar ds along each of the wall's tangents: the wall's
    /// tangential force (friction) averaged over a time step.
    std::array<double, 2> tangential_force_average{};
    /// The step's mean torque of the wall's forces about the axis e_z
    /// through the body's centre (friction's and, off the axis, the
    /// pressure's).
    double torque_average = 0.;
    /// The energy friction dissipated in the step: the mean traction's work
    /// less the change of the stick's elastic energy (>= 0 but where the
    /// Coulomb bound falls within the step).
    double friction_work = 0.;
    /// max(-g): the deepest penetration.
    double max_penetration = 0.;
    /// int p t^2 ds, t the coordinate of the undeformed edge point along the
    /// wall, from the point of the wall nearest the disk's centre.
    double second_moment = 0.;

    /// Half-width (disk) or radius (sphere) of a Hertz profile
    /// p0 sqrt(1 - t^2/a^2) with the same zeroth and second moments:
    /// a = 2 sqrt(second_moment / force) on a strip, a =
    /// sqrt(5 second_moment / (2 force)) on a circle.
    double
    half_width() const;
  };

  /// The size of the smallest face on the curved edge (over all ranks):
  /// its length; in three dimensions the square root of its area, or, for
  /// a body extruded along z (a disk of finite thickness), its area over
  /// its extent along z, the length of its edge in the section as in 2D.
  template <int dim>
  double
  smallest_edge_face(const ElasticityOperator<dim> &op,
                     bool                           extruded_along_z = false);

  /**
   * The contact (a ContactLaw) of the body's curved edge or surface with a
   * rigid wall, on the quadrature points of its faces: the residual
   * contribution -int p (n . v) dS and its consistent tangent -int p'(g)
   * (n . u)(n . v) dS (p' = -k H(-g) for the penalty, H the Heaviside
   * function), for small strains (reference surface, current gap).
   */
  template <int dim>
  class ContactOperator
  {
  public:
    /// With @p circular (a sphere in 3D) the contact is a circle about the
    /// contact point; else a strip (a disk's edge, or its rim in 3D) whose
    /// coordinate runs along the wall's first tangent.
    ContactOperator(const ElasticityOperator<dim>    &op,
                    const RigidWall<dim>             &wall,
                    std::shared_ptr<const ContactLaw> law,
                    const dealii::Point<dim>         &body_center,
                    bool                              circular = false);

    /**
     * Add the contact terms at the displacement @p ghosted_u to @p residual
     * (if not null) and @p tangent (if not null; the caller compresses both)
     * and return the integrals, summed over all ranks.
     */
    ContactState
    assemble(const dealii::PETScWrappers::MPI::Vector &ghosted_u,
             dealii::PETScWrappers::MPI::Vector       *residual,
             dealii::PETScWrappers::MPI::SparseMatrix *tangent) const;

    /// (t, p) at the quadrature points with p > 0, on all ranks, sorted by
    /// t (the coordinate along the wall; for a circle the distance from
    /// the contact point).
    std::vector<std::pair<double, double>>
    pressure_profile(const dealii::PETScWrappers::MPI::Vector &ghosted_u) const;

  private:
    /// The coordinate along the wall of the point @p x of the undeformed
    /// surface.
    double
    coordinate_along_wall(const dealii::Point<dim> &x) const;

    const ElasticityOperator<dim>    &op;
    RigidWall<dim>                    wall;
    std::shared_ptr<const ContactLaw> law;
    bool                              circular;
    /// Where t = 0: the point of the wall nearest the body's centre.
    dealii::Point<dim>     origin;
    dealii::Tensor<1, dim> tangent_direction;
  };
} // namespace DiskImpact
