#pragma once

#include "body/geometry.h"
#include "elasticity/torsion_operator.h"
#include "material/material.h"
#include "modal/modal_analysis.h"
#include "modal/modal_solver.h"

#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <vector>

namespace DiskImpact
{
  /**
   * The torsional (m = 0) modes of a free sphere: the eigenpairs of
   * TorsionOperator on the meridian mesh @p triangulation of the
   * spheroidal modes (ModalAnalysis::get_triangulation()), each
   * labelled (n, l) by the Legendre degree n that carries most of its
   * surface motion, u_phi(R, theta) ~ P_n^1(cos theta), and compared with
   * Lamb's torsional frequencies (Reference::SphereTorsionalModes).
   */
  class TorsionalModalAnalysis
  {
  public:
    TorsionalModalAnalysis(
      const dealii::parallel::distributed::Triangulation<2> &triangulation,
      const BodyGeometry                                    &geometry,
      const Material                                        &material,
      unsigned int                                           fe_degree,
      const ModalSolver                                     &solver,
      dealii::TimerOutput                                   &timer);

    /// The rigid rotation about the axis and the lowest @p n_elastic
    /// torsional modes.
    std::vector<ModeResult>
    run(unsigned int n_elastic);

  private:
    /// The share of each degree n = 0 ... n_max (0 unused) in the surface
    /// motion of @p ghosted_mode: the power c_n^2 |P_n^1|^2 of its
    /// projection on the orthogonal P_n^1(cos theta) with weight
    /// sin theta dtheta, divided by the surface integral of u_phi^2.
    std::vector<double>
    degree_shares(const dealii::PETScWrappers::MPI::Vector &ghosted_mode,
                  unsigned int                              n_max) const;

    const BodyGeometry  &geometry;
    const Material      &material;
    const ModalSolver   &solver;
    dealii::TimerOutput &timer;
    TorsionOperator      op;
  };
} // namespace DiskImpact
