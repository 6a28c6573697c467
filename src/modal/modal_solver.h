#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/petsc_vector.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  template <int dim>
  class DiscreteOperator;
  template <int dim>
  class ElasticityOperator;
  class Material;

  /// Eigenpairs K phi = omega^2 M phi, ascending, phi M-orthonormal.
  struct ModalBasis
  {
    std::vector<double>                             eigenvalues;
    std::vector<dealii::PETScWrappers::MPI::Vector> modes;

    /// omega = sqrt(max(lambda, 0)).
    double
    omega(unsigned int i) const;
  };

  /**
   * The lowest eigenpairs of the free disk, K phi = omega^2 M phi, with
   * SLEPc's Krylov-Schur solver and shift-and-invert about a negative
   * shift (K is singular on a free body), the shifted matrix factorized by
   * MUMPS. SLEPc's own options (-eps_*, -st_*, e.g. through PETSC_OPTIONS)
   * still apply.
   */
  class ModalSolver
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Elastic modes wanted (rigid-body modes come in addition).
    unsigned int
    n_elastic_modes() const;
    void
    set_n_elastic_modes(unsigned int n);
    /// Torsional (azimuthal, m = 0) modes of a sphere wanted beside the
    /// spheroidal ones (task 'modal analysis'; 0: none).
    unsigned int
    n_torsional_modes() const;
    double
    tolerance() const;

    /**
     * The lowest @p n_wanted eigenpairs of @p op (ElasticityOperator or
     * TorsionOperator), whose matrices must be assembled. @p shift is the
     * (negative) shift of the spectral transformation.
     */
    template <int dim>
    ModalBasis
    solve(const DiscreteOperator<dim> &op,
          unsigned int                 n_wanted,
          double                       shift) const;

  private:
    unsigned int n_modes            = 40;
    unsigned int n_torsional        = 0;
    double       relative_tolerance = 1e-10;
  };

  /**
   * Assemble @p op for @p material (timed as "assembly" in @p timer) and
   * move its constrained eigenvalues far above the spectrum; returns the
   * eigenvalue unit (c_T / R)^2, R = @p radius: the rigid-body modes lie
   * many orders below it, the lowest elastic ones near it.
   */
  template <int dim>
  double
  assemble_eigenproblem(ElasticityOperator<dim> &op,
                        const Material          &material,
                        double                   radius,
                        dealii::TimerOutput     &timer);

  /**
   * The modes @p indices of @p basis, eigenvectors of @p op, as one vector
   * field each ("mode_007" for mode 7) in @p directory/modes.pvd and its
   * .vtu files, on the cells curved by @p op's mapping. Collective.
   */
  template <int dim>
  void
  write_mode_shapes(const DiscreteOperator<dim>     &op,
                    const ModalBasis                &basis,
                    const std::vector<unsigned int> &indices,
                    const std::string               &directory);
} // namespace DiskImpact
