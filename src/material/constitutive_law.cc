#include "material/constitutive_law.h"

namespace DiskImpact
{
  using namespace dealii;

  template <int dim>
  void
  ConstitutiveLaw<dim>::initialize_states(
    QuadraturePointStates<dim>                       &states,
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                n_points) const
  {
    states.template initialize<QuadraturePointState>(cell, n_points);
  }

  template <int dim>
  bool
  ConstitutiveLaw<dim>::changes_stiffness() const
  {
    return false;
  }

  template <int dim>
  LinearElasticLaw<dim>::LinearElasticLaw(const Material &material)
      : stiffness(material.stiffness_tensor<dim>())
  {
  }

  template <int dim>
  SymmetricTensor<4, dim>
  LinearElasticLaw<dim>::stiffness_tangent(const QuadraturePointState &) const
  {
    return stiffness;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  LinearElasticLaw<dim>::damping_tangent(const QuadraturePointState &) const
  {
    return SymmetricTensor<4, dim>();
  }

  template <int dim>
  bool
  LinearElasticLaw<dim>::is_viscous() const
  {
    return false;
  }

  template <int dim>
  KelvinVoigtLaw<dim>::KelvinVoigtLaw(const Material &material)
      : LinearElasticLaw<dim>(material)
      , damping(material.damping_tensor<dim>())
  {
  }

  template <int dim>
  SymmetricTensor<4, dim>
  KelvinVoigtLaw<dim>::damping_tangent(const QuadraturePointState &) const
  {
    return damping;
  }

  template <int dim>
  bool
  KelvinVoigtLaw<dim>::is_viscous() const
  {
    return true;
  }

  template <int dim>
  std::unique_ptr<ConstitutiveLaw<dim>>
  make_constitutive_law(const Material &material)
  {
    if (material.is_viscous())
      return std::make_unique<KelvinVoigtLaw<dim>>(material);
    return std::make_unique<LinearElasticLaw<dim>>(material);
  }

  template class ConstitutiveLaw<2>;
  template class ConstitutiveLaw<3>;
  template class LinearElasticLaw<2>;
  template class LinearElasticLaw<3>;
  template class KelvinVoigtLaw<2>;
  template class KelvinVoigtLaw<3>;
  template std::unique_ptr<ConstitutiveLaw<2>>
  make_constitutive_law<2>(const Material &material);
  template std::unique_ptr<ConstitutiveLaw<3>>
  make_constitutive_law<3>(const Material &material);
} // namespace DiskImpact
