#pragma once

#include "material/material.h"

#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/grid/tria.h>

#include <memory>

namespace DiskImpact
{
  /**
   * What a constitutive law keeps at one quadrature point from one step to
   * the next. Laws without memory (elastic, Kelvin-Voigt) keep nothing; a
   * law with memory (plasticity: plastic strain, hardening variable)
   * derives its own state from this one.
   */
  struct QuadraturePointState
  {
    virtual ~QuadraturePointState() = default;
  };

  /// The states of a mesh's locally owned cells, one per quadrature point
  /// (deal.II's CellDataStorage).
  template <int dim>
  using QuadraturePointStates =
    dealii::CellDataStorage<typename dealii::Triangulation<dim>::cell_iterator,
                            QuadraturePointState>;

  /**
   * The constitutive law of a body at its quadrature points: the stress
   * tangent C (d sigma / d eps) and the viscous tangent D
   * (sigma_v = D : eps_dot) at a point with its state. ElasticityOperator
   * assembles K and D from them and keeps the states. A law whose tangent
   * changes with its state says so (changes_stiffness()): K is then
   * reassembled where the state changed and the stepper refactorizes
   * (ContactStepper::refactorize()).
   */
  template <int dim>
  class ConstitutiveLaw
  {
  public:
    virtual ~ConstitutiveLaw() = default;

    /// Create the states of @p cell's @p n_points quadrature points in
    /// @p states (by default the empty QuadraturePointState).
    virtual void
    initialize_states(
      QuadraturePointStates<dim>                               &states,
      const typename dealii::Triangulation<dim>::cell_iterator &cell,
      unsigned int                                              n_points) const;
    virtual dealii::SymmetricTensor<4, dim>
    stiffness_tangent(const QuadraturePointState &state) const = 0;
    virtual dealii::SymmetricTensor<4, dim>
    damping_tangent(const QuadraturePointState &state) const = 0;
    /// Whether D is not zero.
    virtual bool
    is_viscous() const = 0;
    /// Whether the tangents change with the states (false: K and D are
    /// assembled once).
    virtual bool
    changes_stiffness() const;
  };

  /// Linear isotropic elasticity: C of the material, D = 0.
  template <int dim>
  class LinearElasticLaw : public ConstitutiveLaw<dim>
  {
  public:
    explicit LinearElasticLaw(const Material &material);
    dealii::SymmetricTensor<4, dim>
    stiffness_tangent(const QuadraturePointState &state) const override;
    dealii::SymmetricTensor<4, dim>
    damping_tangent(const QuadraturePointState &state) const override;
    bool
    is_viscous() const override;

  private:
    dealii::SymmetricTensor<4, dim> stiffness;
  };

  /// Kelvin-Voigt viscoelasticity: C and D of the material
  /// (Material::damping_tensor()).
  template <int dim>
  class KelvinVoigtLaw : public LinearElasticLaw<dim>
  {
  public:
    explicit KelvinVoigtLaw(const Material &material);
    dealii::SymmetricTensor<4, dim>
    damping_tangent(const QuadraturePointState &state) const override;
    bool
    is_viscous() const override;

  private:
    dealii::SymmetricTensor<4, dim> damping;
  };

  /// The law of @p material: Kelvin-Voigt if it is viscous, else linear
  /// elastic.
  template <int dim>
  std::unique_ptr<ConstitutiveLaw<dim>>
  make_constitutive_law(const Material &material);
} // namespace DiskImpact
