#pragma once

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "material/material.h"
#include "modal/modal_solver.h"
#include "reference/free_body_modes.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /// One computed mode of the solid sphere, labelled from its shape.
  struct SolidModeResult
  {
    unsigned int         index = 0;
    double               omega = 0.;
    Reference::ModeLabel label;
    /// The number of modes of its frequency (within the clustering
    /// tolerance): 2n + 1 for the degree n of a sphere's mode.
    unsigned int multiplicity = 1;
    /// int (u . e_r)^2 dV / int |u|^2 dV: 0 for a torsional mode.
    double radial_fraction = 0.;
    /// Lamb's omega of the same label; 0 for rigid or unlabelled modes.
    double omega_exact = 0.;
    /// Whether the label follows from the shape: the multiplicity is odd.
    bool labelled = true;

    bool
    is_rigid() const;
    /// omega / omega_exact - 1 (labelled elastic modes).
    double
    relative_error() const;
  };

  /**
   * Modal analysis of the free sphere in three dimensions (create_solid_
   * triangulation(), ElasticityOperator<3>): no symmetry is assumed, so each
   * degree n appears with its 2n + 1 modes. Each mode is labelled from its
   * shape, not from its frequency: its multiplicity (the size of its
   * cluster of equal frequencies) gives n, its surface motion the family
   * (torsional: no radial motion), the count of lower clusters of the same
   * family and n the overtone l. Lamb's frequency of that label
   * (Reference::FreeSphereModes, Reference::SphereTorsionalModes) is then
   * the reference.
   */
  class SolidModalAnalysis
  {
  public:
    /// Frequencies closer than this (relative) form one cluster: far above
    /// the splitting of a multiplet by a converged mesh, far below the
    /// gaps between the sphere's distinct frequencies.
    static constexpr double cluster_tolerance = 1e-4;
    /// Modes whose motion has a radial share below this are torsional:
    /// theirs is the discretization error (at most 3.5e-7 on the meshes of
    /// params/ and tests/), the spheroidal modes' at least 0.25 among the
    /// lowest 51.
    static constexpr double torsional_radial_fraction = 1e-3;

    SolidModalAnalysis(const BodyGeometry  &geometry,
                       const Material      &material,
                       unsigned int         fe_degree,
                       const ModalSolver   &solver,
                       MPI_Comm             communicator,
                       dealii::TimerOutput &timer);

    /// The six rigid-body modes and the lowest @p n_elastic elastic ones,
    /// more if the last multiplet is not complete.
    std::vector<SolidModeResult>
    run(unsigned int n_elastic);

    dealii::types::global_dof_index
    n_dofs() const;
    unsigned int
    n_cells() const;

    /// modes.csv of a solid (docs/reference/output-files.md).
    static void
    write_modes_csv(const std::vector<SolidModeResult> &modes,
                    const std::string                  &filename);
    /// Mode shapes (field mode_NNN per mode) as modes.pvd + modes_*.vtu.
    void
    write_mode_shapes(const std::vector<SolidModeResult> &modes,
                      const std::string                  &directory) const;
    /// The frequency table on the terminal, one line per multiplet.
    static void
    print_table(const std::vector<SolidModeResult> &modes,
                dealii::ConditionalOStream         &out);

  private:
    /// The radial share of the motion of @p ghosted_mode.
    double
    radial_fraction(
      const dealii::PETScWrappers::MPI::Vector &ghosted_mode) const;
    /// Labels, multiplicities and Lamb's frequencies of @p modes (omega
    /// and radial_fraction set), in place.
    void
    label(std::vector<SolidModeResult> &modes) const;

    const BodyGeometry                             &geometry;
    const Material                                 &material;
    const ModalSolver                              &solver;
    dealii::TimerOutput                            &timer;
    dealii::parallel::distributed::Triangulation<3> triangulation;
    ElasticityOperator<3>                           op;
    ModalBasis                                      basis;
  };
} // namespace DiskImpact
