#include "material/material.h"

#include "base/input_error.h"

#include <cmath>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  void
  Material::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Plane model",
                        "",
                        Patterns::Selection("|plane strain|plane stress"),
                        "Disks only: 'plane stress' (thin plate; the "
                        "constants are the in-plane ones; the default when "
                        "empty) or 'plane strain' (long cylinder; Young "
                        "modulus and Poisson ratio are the 3D constants). "
                        "Must be empty for a sphere, whose constants are the "
                        "3D ones.");
      prm.declare_entry("Young modulus",
                        "1",
                        Patterns::Double(),
                        "Young modulus E [force/area]: the 3D value for "
                        "plane strain, the in-plane value for plane stress. "
                        "Must be positive.");
      prm.declare_entry("Poisson ratio",
                        "0.3",
                        Patterns::Double(),
                        "Poisson ratio nu [-]: -1 < nu < 0.5 for plane strain, "
                        "-1 < nu <= 0.5 for plane stress.");
      prm.declare_entry("Density",
                        "1",
                        Patterns::Double(),
                        "Mass density rho [mass/area, i.e. per unit "
                        "thickness, for a disk; mass/volume for a sphere]. "
                        "Must be positive.");
      prm.declare_entry("Relaxation time",
                        "0",
                        Patterns::Double(),
                        "Kelvin-Voigt relaxation time tau [time]: "
                        "sigma = C:eps + tau C:eps_dot. 0 is purely elastic; "
                        "must not be negative.");
      prm.declare_entry("Shear viscosity",
                        "0",
                        Patterns::Double(),
                        "In-plane shear viscosity eta_s [stress * time]: "
                        "adds 2 eta_s dev(eps_dot) to the stress (dev the "
                        "in-plane deviator). Must not be negative.");
      prm.declare_entry("Bulk viscosity",
                        "0",
                        Patterns::Double(),
                        "In-plane bulk viscosity eta_b [stress * time]: adds "
                        "eta_b tr(eps_dot) 1 to the stress. Must not be "
                        "negative.");
      prm.declare_entry("Yield stress",
                        "0",
                        Patterns::Double(),
                        "Von Mises yield stress Y [force/area] (uniaxial): "
                        "0 is elastic; above 0 the body is elastic-plastic "
                        "(J2 flow, radial return; in plane stress with "
                        "sigma_zz = 0 at every point). Must not be "
                        "negative.");
      prm.declare_entry("Hardening modulus",
                        "0",
                        Patterns::Double(),
                        "Linear isotropic hardening modulus H [force/area]: "
                        "the yield stress grows as Y + H alpha with the "
                        "equivalent plastic strain alpha. 0 is perfectly "
                        "plastic; must not be negative.");
    }
    prm.leave_subsection();
  }

  void
  Material::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    const std::string name = prm.get("Plane model");
    model_given            = !name.empty();
    const PlaneModel m     = name == "plane strain" ? PlaneModel::plane_strain :
                                                      PlaneModel::plane_stress;
    set(m,
        prm.get_double("Young modulus"),
        prm.get_double("Poisson ratio"),
        prm.get_double("Density"),
        prm.get_double("Relaxation time"));
    set_viscosities(prm.get_double("Shear viscosity"),
                    prm.get_double("Bulk viscosity"));
    set_plasticity(prm.get_double("Yield stress"),
                   prm.get_double("Hardening modulus"));
    prm.leave_subsection();
  }

  void
  Material::set(const PlaneModel plane_model,
                const double     young_modulus,
                const double     poisson_ratio,
                const double     density,
                const double     relaxation_time)
  {
    require(young_modulus > 0,
            "Material: 'Young modulus' must be positive, got " +
              std::to_string(young_modulus));
    require(density > 0,
            "Material: 'Density' must be positive, got " +
              std::to_string(density));
    require(relaxation_time >= 0,
            "Material: 'Relaxation time' must not be negative, got " +
              std::to_string(relaxation_time));
    if (plane_model != PlaneModel::plane_stress)
      require(poisson_ratio > -1 && poisson_ratio < 0.5,
              "Material: 'Poisson ratio' must satisfy -1 < nu < 0.5 in " +
                DiskImpact::plane_model_name(plane_model) +
                " (the bulk modulus is infinite at nu = 0.5), got " +
                std::to_string(poisson_ratio));
    else
      require(poisson_ratio > -1 && poisson_ratio <= 0.5,
              "Material: 'Poisson ratio' must satisfy -1 < nu <= 0.5 in "
              "plane stress, got " +
                std::to_string(poisson_ratio));
    model          = plane_model;
    young          = young_modulus;
    poisson        = poisson_ratio;
    rho            = density;
    relaxation_tau = relaxation_time;
  }

  bool
  Material::plane_model_given() const
  {
    return model_given;
  }

  void
  Material::make_axisymmetric()
  {
    require(shear_eta == 0. && bulk_eta == 0.,
            "Material: 'Shear viscosity' and 'Bulk viscosity' are in-plane "
            "viscosities of a disk; a sphere takes 'Relaxation time' only");
    set(PlaneModel::axisymmetric, young, poisson, rho, relaxation_tau);
  }

  double
  Material::poisson_ratio() const
  {
    return poisson;
  }

  Material
  Material::with_poisson_ratio(const double nu) const
  {
    Material other = *this;
    other.set(model, young, nu, rho, relaxation_tau);
    return other;
  }

  Material
  Material::with_relaxation_time(const double tau) const
  {
    Material other = *this;
    other.set(model, young, poisson, rho, tau);
    return other;
  }

  PlaneModel
  Material::plane_model() const
  {
    return model;
  }

  std::string
  plane_model_name(const PlaneModel model)
  {
    switch (model)
      {
        case PlaneModel::plane_strain:
          return "plane strain";
        case PlaneModel::plane_stress:
          return "plane stress";
        case PlaneModel::axisymmetric:
          return "axisymmetric";
      }
    return "unknown";
  }

  std::string
  Material::plane_model_name() const
  {
    return DiskImpact::plane_model_name(model);
  }

  double
  Material::young_modulus() const
  {
    return young;
  }

  double
  Material::density() const
  {
    return rho;
  }

  double
  Material::relaxation_time() const
  {
    return relaxation_tau;
  }

  double
  Material::in_plane_young_modulus() const
  {
    return model == PlaneModel::plane_stress ? young :
                                               young / (1. - poisson * poisson);
  }

  double
  Material::in_plane_poisson_ratio() const
  {
    return model == PlaneModel::plane_stress ? poisson :
                                               poisson / (1. - poisson);
  }

  double
  Material::shear_modulus() const
  {
    return in_plane_young_modulus() / (2. * (1. + in_plane_poisson_ratio()));
  }

  double
  Material::lame_lambda() const
  {
    const double nu2 = in_plane_poisson_ratio();
    return in_plane_young_modulus() * nu2 / (1. - nu2 * nu2);
  }

  template <int dim>
  SymmetricTensor<4, dim>
  Material::stiffness_tensor() const
  {
    // In three dimensions the Lame constants of E and nu (a plane-strain
    // disk's in-plane constants are the same).
    const double mu     = dim == 2 ? shear_modulus() : shear_modulus_3d();
    const double lambda = dim == 2 ? lame_lambda() : lame_lambda_3d();
    SymmetricTensor<4, dim> c;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            c[i][j][k][l] = lambda * (i == j) * (k == l) +
                            mu * ((i == k) * (j == l) + (i == l) * (j == k));
    return c;
  }

  void
  Material::set_viscosities(const double shear_viscosity,
                            const double bulk_viscosity)
  {
    require(shear_viscosity >= 0. && bulk_viscosity >= 0.,
            "Material: 'Shear viscosity' and 'Bulk viscosity' must not be "
            "negative, got " +
              std::to_string(shear_viscosity) + " and " +
              std::to_string(bulk_viscosity));
    shear_eta = shear_viscosity;
    bulk_eta  = bulk_viscosity;
  }

  void
  Material::set_plasticity(const double yield_stress,
                           const double hardening_modulus)
  {
    require(yield_stress >= 0. && hardening_modulus >= 0.,
            "Material: 'Yield stress' and 'Hardening modulus' must not be "
            "negative, got " +
              std::to_string(yield_stress) + " and " +
              std::to_string(hardening_modulus));
    yield     = yield_stress;
    hardening = hardening_modulus;
  }

  bool
  Material::is_plastic() const
  {
    return yield > 0.;
  }

  double
  Material::yield_stress() const
  {
    return yield;
  }

  double
  Material::hardening_modulus() const
  {
    return hardening;
  }

  double
  Material::lame_lambda_3d() const
  {
    return young * poisson / ((1. + poisson) * (1. - 2. * poisson));
  }

  double
  Material::shear_modulus_3d() const
  {
    return young / (2. * (1. + poisson));
  }

  template <int dim>
  SymmetricTensor<4, dim>
  Material::damping_tensor() const
  {
    const auto one_one =
      outer_product(unit_symmetric_tensor<dim>(), unit_symmetric_tensor<dim>());
    return relaxation_tau * stiffness_tensor<dim>() +
           2. * shear_eta * (identity_tensor<dim>() - one_one / dim) +
           bulk_eta * one_one;
  }

  template SymmetricTensor<4, 2>
  Material::stiffness_tensor<2>() const;
  template SymmetricTensor<4, 3>
  Material::stiffness_tensor<3>() const;
  template SymmetricTensor<4, 2>
  Material::damping_tensor<2>() const;
  template SymmetricTensor<4, 3>
  Material::damping_tensor<3>() const;

  bool
  Material::is_viscous() const
  {
    return relaxation_tau > 0. || shear_eta > 0. || bulk_eta > 0.;
  }

  double
  Material::longitudinal_wave_speed() const
  {
    return std::sqrt((lame_lambda() + 2. * shear_modulus()) / rho);
  }

  double
  Material::transverse_wave_speed() const
  {
    return std::sqrt(shear_modulus() / rho);
  }

  double
  Material::velocity_unit() const
  {
    return std::sqrt(in_plane_young_modulus() / rho);
  }

  void
  Material::print_summary(ConditionalOStream &out, const bool solid) const
  {
    std::ostringstream s;
    s.precision(10);
    s << "Material: "
      << (solid ?
            "3D (units and estimates of the " + plane_model_name() + " model)" :
            plane_model_name())
      << ", E = " << young << ", nu = " << poisson << ", rho = " << rho
      << ", relaxation time = " << relaxation_tau << ", viscosities: shear "
      << shear_eta << ", bulk " << bulk_eta << '\n'
      << "  in-plane constants: E2 = " << in_plane_young_modulus()
      << ", nu2 = " << in_plane_poisson_ratio() << ", mu = " << shear_modulus()
      << ", lambda2 = " << lame_lambda() << '\n'
      << "  wave speeds: c_L = " << longitudinal_wave_speed()
      << ", c_T = " << transverse_wave_speed()
      << ", velocity unit c = sqrt(E2/rho) = " << velocity_unit() << '\n';
    if (is_plastic())
      s << "  plasticity: von Mises, yield stress Y = " << yield
        << ", hardening modulus H = " << hardening << '\n';
    out << s.str();
  }
} // namespace DiskImpact
