#pragma once

#include "elasticity/elasticity_operator.h"
#include "material/j2_return_mapping.h"
#include "material/material.h"

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <memory>
#include <vector>

namespace DiskImpact
{
  /**
   * The plastic strain of an elastic-plastic body (von Mises, J2ReturnMapping)
   * at the quadrature points of the elasticity operator's assembly, and the
   * force it exerts on the elastic operator: the internal force of a
   * displacement u is K u - f_p with f_p = int eps(v) : C : eps_p dV (the
   * initial-strain form, so K and its factorization stay elastic).
   *
   * A time step evaluates trial states at its end displacement (the return
   * mapping from the accepted states, as often as its iteration needs) and
   * accepts the last. The plastic work of a step is
   * int (eps_p1 - eps_p0) : (sigma_0 + sigma_1) / 2 dV: with the midpoint
   * rule's internal force (K u - f_p at both ends, halves), kinetic +
   * elastic energy + this work is conserved by the step
   * (docs/theory/plasticity.md).
   *
   * The strains are three-dimensional: plane strain adds eps_zz = 0, the
   * axisymmetric meridian its hoop strain (Section). Cells whose material is
   * elastic are skipped. A plane-stress disk takes PlaneStressReturnMapping
   * (sigma_zz = 0, its eps_zz found per point).
   */
  template <int dim>
  class PlasticStrainField
  {
  public:
    /// For @p op as assembled with @p materials (by material id).
    PlasticStrainField(const ElasticityOperator<dim> &op,
                       const std::vector<Material>   &materials);

    /// Trial states at the displacement @p u (constraints satisfied) from
    /// the accepted ones, and their force f_p into @p force. With
    /// @p all_cells false only on the cells the last evaluation of all
    /// cells found near yield (a von Mises stress above 0.8 of the yield
    /// stress, or plastic strain): the others keep their trial states. A
    /// step's last evaluation must be of all cells. With @p tangent also
    /// add int eps(v) : (C_ep - C) : eps(w) dV of the yielding points to it
    /// (C_ep the return mapping's consistent tangent), so that K plus it
    /// is the derivative of K u - f_p (Newton's tangent). Collective.
    void
    evaluate(const dealii::PETScWrappers::MPI::Vector &u,
             dealii::PETScWrappers::MPI::Vector       &force,
             bool                                      all_cells = true,
             dealii::PETScWrappers::MPI::SparseMatrix *tangent   = nullptr);
    /// Accept the last trial states; the plastic work since the last
    /// accepted states (over the section's volume). Collective.
    double
    accept();

    /// int eps_p : C : eps_p dV / 2 of the accepted states: the elastic
    /// energy is u.(K u)/2 - u.f_p + this.
    double
    plastic_strain_energy() const;
    /// The same over the cells of material id @p body.
    double
    plastic_strain_energy(unsigned int body) const;
    /// The largest equivalent plastic strain alpha of the accepted states.
    /// Collective.
    double
    largest_equivalent_plastic_strain() const;
    /// The quadrature points that yielded in the last evaluation. Collective.
    unsigned int
    n_yielding_points() const;
    /// The points whose yielding in the last evaluation differs from the
    /// last evaluation with a tangent (the plastic zone's change since
    /// Newton's matrix was assembled; points of cells the evaluation
    /// skipped are not counted). Collective.
    unsigned int
    n_changed_since_tangent() const;
    /// Each active cell's largest accepted alpha (0 on cells not locally
    /// owned), for graphical output.
    dealii::Vector<float>
    equivalent_plastic_strain_per_cell() const;
    /// Each active cell's largest von Mises stress of the accepted states
    /// (0 on cells not locally owned and on elastic cells).
    dealii::Vector<float>
    von_mises_stress_per_cell() const;

  private:
    /// The accepted and trial states of one quadrature point.
    struct Point
    {
      J2ReturnMapping::State        accepted, trial;
      dealii::SymmetricTensor<2, 3> stress, trial_stress;
      /// dV of the point (JxW times the section's measure).
      double volume = 0.;
      /// Whether it yielded in the last evaluation with a tangent.
      bool in_tangent = false;
    };

    /// The largest @p value of each locally owned cell's points.
    dealii::Vector<float>
    largest_per_cell(const std::function<double(const Point &)> &value) const;

    const ElasticityOperator<dim> &op;
    /// Each material's return mapping (null where it is elastic).
    std::vector<std::unique_ptr<J2ReturnMapping>> return_mappings;
    /// The points of each locally owned cell, by active cell index (empty
    /// elsewhere), and whether the cell is near yield.
    std::vector<std::vector<Point>> points;
    std::vector<bool>               near_yield;
    unsigned int                    yielding = 0, changed_since_tangent = 0;
    /// int eps_p : C : eps_p dV / 2 of the accepted states per material.
    std::vector<double> strain_energy_terms;
  };
} // namespace DiskImpact
