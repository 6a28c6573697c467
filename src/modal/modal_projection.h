#pragma once

#include "modal/modal_solver.h"
#include "modal/mode_labelling.h"

#include <deal.II/lac/petsc_vector.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  class CsvTable;
  class BodyGeometry;
  template <int dim>
  class ElasticityOperator;

  /**
   * The vibration of an impact in the eigenmodes of the same
   * discretization: the lowest elastic modes K phi = omega^2 M phi
   * (M-orthonormal, ModalSolver) of the operator the time integrator uses,
   * labelled (n, l, family) from their edge motion; the modal coordinates
   * q = phi^T M u, q' = phi^T M v give each mode's energy
   * (q'^2 + omega^2 q^2) / 2. Gerl & Zippelius' Table 1 ranks the modes by
   * their energy averaged over the collision, accumulated by add_sample().
   */
  class ModalProjection
  {
  public:
    /// Modes of @p op (assembled; its constrained rows get a far
    /// eigenvalue, harmless for time stepping, where they are zeroed).
    ModalProjection(ElasticityOperator<2> &op,
                    const BodyGeometry    &geometry,
                    double                 eigenvalue_scale,
                    unsigned int           n_elastic_modes);

    /// Energy of each elastic mode in the state (u, v).
    std::vector<double>
    energies(const dealii::PETScWrappers::MPI::Vector &u,
             const dealii::PETScWrappers::MPI::Vector &v) const;

    /// Add the energies of (u, v) with weight @p dt to the collision average.
    void
    add_sample(const dealii::PETScWrappers::MPI::Vector &u,
               const dealii::PETScWrappers::MPI::Vector &v,
               double                                    dt);

    /**
     * mode_energies.csv: rank (by energy after the impact), n, l, family,
     * omega, energy_fraction (after the impact) and
     * average_energy_fraction (during it), both as fractions of
     * @p reference_energy (the initial kinetic energy) and multiplied by
     * @p factor (2 on a half disk).
     */
    CsvTable
    table(const dealii::PETScWrappers::MPI::Vector &u,
          const dealii::PETScWrappers::MPI::Vector &v,
          double                                    reference_energy,
          double                                    factor) const;

  private:
    ModalBasis basis;
    /// M phi_i as functionals: q_i = mass_modes[i] . u.
    std::vector<dealii::PETScWrappers::MPI::Vector> mass_modes;
    std::vector<LabelledMode>                       labels;
    /// The first elastic mode (after the rigid ones).
    unsigned int        first_elastic = 0;
    std::vector<double> energy_time_integral;
    double              sampled_time = 0.;
  };
} // namespace DiskImpact
