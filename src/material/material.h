#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <string>

namespace DiskImpact
{
  /// How the two-dimensional model is obtained from a three-dimensional
  /// body.
  enum class PlaneModel
  {
    plane_strain,
    plane_stress,
    /// A body of revolution on its meridian (the sphere): the 3D constants,
    /// with the in-plane constants of plane strain for the meridian's
    /// strains and the hoop strain added by the weak form.
    axisymmetric
  };

  std::string
  plane_model_name(PlaneModel model);

  /**
   * A linear elastic (optionally Kelvin-Voigt) isotropic material in two
   * dimensions. Plane strain with the 3D constants (E, nu) has the same
   * equations as plane stress with the in-plane constants
   * E2 = E / (1 - nu^2), nu2 = nu / (1 - nu) (Gerl & Zippelius 1999, eq. 2);
   * everything below is expressed through the in-plane constants.
   */
  class Material
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Whether 'Plane model' was given (it must not be for a sphere).
    bool
    plane_model_given() const;
    /// Switch to the axisymmetric model (a sphere), keeping the constants;
    /// the in-plane viscosities must be zero.
    void
    make_axisymmetric();

    /// Set the constants directly (as parse_parameters() does), with checks.
    void
    set(PlaneModel model,
        double     young_modulus,
        double     poisson_ratio,
        double     density,
        double     relaxation_time = 0.);

    /// The Poisson ratio as given (3D for plane strain).
    double
    poisson_ratio() const;

    /// The same material with another Poisson ratio (checked).
    Material
    with_poisson_ratio(double nu) const;

    /// The same material with another relaxation time (checked).
    Material
    with_relaxation_time(double tau) const;

    PlaneModel
    plane_model() const;
    std::string
    plane_model_name() const;
    /// The 'Young modulus' entry: the 3D E (the in-plane one in plane
    /// stress).
    double
    young_modulus() const;
    double
    density() const;
    double
    relaxation_time() const;

    /// In-plane Young modulus E2 and Poisson ratio nu2 (Gerl & Zippelius 1999,
    /// eq. 2).
    double
    in_plane_young_modulus() const;
    double
    in_plane_poisson_ratio() const;

    /// Lame constants of the two-dimensional problem.
    double
    shear_modulus() const;
    double
    lame_lambda() const;

    /// sigma = C : eps: in two dimensions with the in-plane constants of
    /// the plane model, in three with E and nu.
    template <int dim>
    dealii::SymmetricTensor<4, dim>
    stiffness_tensor() const;

    /// In-plane viscosities of the general Kelvin-Voigt law (checked >= 0).
    void
    set_viscosities(double shear_viscosity, double bulk_viscosity);
    /**
     * The viscous stress sigma_v = D : eps_dot of the Kelvin-Voigt law:
     * D = tau C + 2 eta_s (I - 1 x 1 / 2) + eta_b 1 x 1, i.e. the relaxation
     * time's part proportional to C and separate in-plane shear (deviatoric)
     * and bulk viscosities (1 x 1 / dim in three dimensions).
     */
    template <int dim>
    dealii::SymmetricTensor<4, dim>
    damping_tensor() const;
    /// Whether D is not zero.
    bool
    is_viscous() const;

    /// Von Mises plasticity with linear isotropic hardening: the yield
    /// stress Y (0: elastic) and the hardening modulus H (0: perfectly
    /// plastic), both checked >= 0.
    void
    set_plasticity(double yield_stress, double hardening_modulus);
    bool
    is_plastic() const;
    double
    yield_stress() const;
    double
    hardening_modulus() const;
    /// Lame's constants of the three-dimensional material (those of the
    /// plasticity of plane strain, the axisymmetric and the 3D body).
    double
    lame_lambda_3d() const;
    double
    shear_modulus_3d() const;

    /// Longitudinal and transverse wave speeds, and the velocity unit of Gerl &
    /// Zippelius c = sqrt(E2 / rho).
    double
    longitudinal_wave_speed() const;
    double
    transverse_wave_speed() const;
    double
    velocity_unit() const;

    /// Print the model, the input and the derived constants; for a body
    /// computed in 3D (@p solid), whose stiffness is the 3D one of E and
    /// nu, the model named is the one that sets the units and estimates.
    void
    print_summary(dealii::ConditionalOStream &out, bool solid = false) const;

  private:
    PlaneModel model          = PlaneModel::plane_strain;
    bool       model_given    = true;
    double     young          = 1.;
    double     poisson        = 0.3;
    double     rho            = 1.;
    double     relaxation_tau = 0.;
    double     shear_eta      = 0.;
    double     bulk_eta       = 0.;
    double     yield          = 0.;
    double     hardening      = 0.;
  };
} // namespace DiskImpact
