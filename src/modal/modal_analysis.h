#pragma once

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "material/material.h"
#include "modal/modal_solver.h"
#include "modal/mode_labelling.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <memory>
#include <string>
#include <vector>

namespace DiskImpact
{
  /// One computed mode beside its analytic counterpart.
  struct ModeResult
  {
    unsigned int         index = 0;
    double               omega = 0.;
    Reference::ModeLabel label;
    double               harmonic_fraction = 1.;
    /// Share of the boundary motion's power in even orders (a sphere's
    /// z-parity: even above 1/2).
    double even_order_fraction = 1.;
    /// The analytic omega of the same label; 0 for rigid modes.
    double omega_exact = 0.;

    bool
    is_rigid() const;
    /// omega / omega_exact - 1 (elastic modes).
    double
    relative_error() const;
  };

  /// The analytic free modes of the body (disk: Bessel, sphere: Lamb)
  /// @p geometry and @p material describe.
  std::unique_ptr<Reference::FreeBodyModes>
  analytic_free_modes(const BodyGeometry &geometry, const Material &material);

  /**
   * Modal analysis of the free body on one mesh and degree: builds the mesh
   * and the elasticity operator, solves the eigenproblem, labels each mode
   * (n, l, family) from its boundary motion and compares it with the
   * analytic mode of the same label.
   */
  class ModalAnalysis
  {
  public:
    ModalAnalysis(const BodyGeometry  &geometry,
                  const Material      &material,
                  unsigned int         fe_degree,
                  const ModalSolver   &solver,
                  MPI_Comm             communicator,
                  dealii::TimerOutput &timer);

    /// Compute the rigid-body modes and the lowest @p n_elastic elastic
    /// ones (one more if that completes a pair of a degenerate frequency).
    std::vector<ModeResult>
    run(unsigned int n_elastic);

    dealii::types::global_dof_index
    n_dofs() const;
    /// The meridian (or disk) mesh, for a further operator on it.
    const dealii::parallel::distributed::Triangulation<2> &
    get_triangulation() const;
    /// Largest cell diameter.
    double
    mesh_size() const;
    unsigned int
    n_cells() const;

    /// modes.csv (docs/reference/output-files.md); a sphere's has the
    /// z_parity column.
    static void
    write_modes_csv(const std::vector<ModeResult> &modes,
                    const std::string             &filename,
                    bool                           with_z_parity = false);
    /// Mode shapes (field mode_NNN per mode) as modes.pvd + modes_*.vtu.
    void
    write_mode_shapes(const std::vector<ModeResult> &modes,
                      const std::string             &directory) const;
    /// The frequency table on the terminal.
    static void
    print_table(const std::vector<ModeResult> &modes,
                dealii::ConditionalOStream    &out);

  private:
    const BodyGeometry                             &geometry;
    const Material                                 &material;
    const ModalSolver                              &solver;
    MPI_Comm                                        communicator;
    dealii::TimerOutput                            &timer;
    dealii::parallel::distributed::Triangulation<2> triangulation;
    ElasticityOperator<2>                           op;
    ModalBasis                                      basis;
  };
} // namespace DiskImpact
