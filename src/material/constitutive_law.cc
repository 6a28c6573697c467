#include "material/constitutive_law.h"

namespace DiskImpact
{
  using namespace dealii;

  void
  ConstitutiveLaw::initialize_states(
    QuadraturePointStates                 &states,
    const Triangulation<2>::cell_iterator &cell,
    const unsigned int                     n_points) const
  {
    states.initialize<QuadraturePointState>(cell, n_points);
  }

  bool
  ConstitutiveLaw::changes_stiffness() const
  {
    return false;
  }

  LinearElasticLaw::LinearElasticLaw(const Material &material)
      : stiffness(material.stiffness_tensor())
  {
  }

  SymmetricTensor<4, 2>
  LinearElasticLaw::stiffness_tangent(const QuadraturePointState &) const
  {
    return stiffness;
  }

  SymmetricTensor<4, 2>
  LinearElasticLaw::damping_tangent(const QuadraturePointState &) const
  {
    return SymmetricTensor<4, 2>();
  }

  bool
  LinearElasticLaw::is_viscous() const
  {
    return false;
  }

  KelvinVoigtLaw::KelvinVoigtLaw(const Material &material)
      : LinearElasticLaw(material)
      , damping(material.damping_tensor())
  {
  }

  SymmetricTensor<4, 2>
  KelvinVoigtLaw::damping_tangent(const QuadraturePointState &) const
  {
    return damping;
  }

  bool
  KelvinVoigtLaw::is_viscous() const
  {
    return true;
  }

  std::unique_ptr<ConstitutiveLaw>
  make_constitutive_law(const Material &material)
  {
    if (material.is_viscous())
      return std::make_unique<KelvinVoigtLaw>(material);
    return std::make_unique<LinearElasticLaw>(material);
  }
} // namespace DiskImpact
