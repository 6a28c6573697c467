#pragma once

#include "elasticity/discrete_operator.h"

#include <deal.II/distributed/tria.h>

#include <deal.II/fe/fe_q.h>

namespace DiskImpact
{
  class BodyGeometry;
  class Material;

  /**
   * The torsional (azimuthal) motion of an axisymmetric body: the scalar
   * u_phi = w(r, z) on the meridian (r = y, z = x; class Section), which
   * decouples from the meridian's (u_r, u_z). Its only strains are
   * eps_{r phi} = (w_r - w / r) / 2 and eps_{z phi} = w_z / 2, so
   *
   *   K: mu int [(w_r - w/r)(v_r - v/r) + w_z v_z] 2 pi r dA,
   *   M: rho int w v 2 pi r dA,
   *
   * with Q_k elements, a degree-k boundary mapping and w = 0 on the axis.
   * K's null space is the rigid rotation about the axis, w = r.
   */
  class TorsionOperator : public DiscreteOperator<2>
  {
  public:
    explicit TorsionOperator(unsigned int degree);

    /// Distribute DoFs on @p triangulation (a sphere's meridian) and build
    /// constraints and matrix patterns.
    void
    setup(const dealii::parallel::distributed::Triangulation<2> &triangulation,
          const BodyGeometry                                    &geometry);

    /// Assemble K and M of @p material.
    void
    assemble(const Material &material);

  private:
    dealii::FE_Q<2> fe;
  };
} // namespace DiskImpact
