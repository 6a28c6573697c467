#pragma once

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace DiskImpact
{
  /// What a contact law is scaled by: the pair's in-plane Young modulus E2,
  /// the length h of the smallest edge face at the contact point and the
  /// body's radius R.
  struct ContactScales
  {
    double modulus      = 1.;
    double element_size = 1.;
    double radius       = 1.;
  };

  /**
   * A law of normal contact: the wall's pressure p on an edge point as a
   * function of its gap g (g < 0: the point is beyond the plane where the
   * law starts to act), p >= 0, with its energy per unit boundary length
   * (E' = -p). Each law is one file pair: a class derived from this one,
   * with a static declare_parameters(prm) for its entries in subsection
   * Contact, and one registration line
   *
   *   DISKIMPACT_REGISTER_CONTACT_LAW(Class, "name", "description")
   *
   * which makes it selectable as 'Law = name'. (The exact constraint
   * g >= 0 is no law of this kind: its pressure is a Lagrange multiplier,
   * found by a solver of its own, ContactStepper.)
   */
  class ContactLaw
  {
  public:
    virtual ~ContactLaw() = default;

    /// A copy (laws are parsed once and scaled per mesh).
    virtual std::unique_ptr<ContactLaw>
    clone() const = 0;
    /// Read the law's entries; @p prm is in subsection Contact.
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;
    /// Set the scales of a mesh and material before use.
    virtual void
    set_scales(const ContactScales &scales) = 0;
    /// Make the law @p factor times stiffer where it regularizes hard
    /// contact (a convergence study's 'penalty' factor); by default the law
    /// is no regularization and stays as it is.
    virtual void
    stiffen(double factor);
    /// Whether the law approximates hard contact (g >= 0), so that the
    /// hard-contact models (the 1-DOF log law) bound its impacts.
    virtual bool
    approximates_hard_contact() const;

    virtual double
    pressure(double gap) const = 0;
    /// dp / dg.
    virtual double
    pressure_derivative(double gap) const = 0;
    virtual double
    energy(double gap) const = 0;
    /// How far beyond the law's plane the pressure reaches the order of E2
    /// (0 by default: the law acts from g = 0 on).
    virtual double
    reach() const;
    /// The stiffness [pressure / length] of the elastic stick that
    /// regularizes Coulomb friction: the tangential traction changes by
    /// -k_t times the tangential displacement while a point sticks.
    virtual double
    tangential_stiffness() const;
    /// Whether the law has a tangential_stiffness(), so that 'Friction
    /// coefficient' > 0 can act with it (false by default).
    virtual bool
    supports_friction() const;

    /**
     * The pressure averaged over a time step in which the gap goes from
     * @p g0 to @p g1, the discrete gradient of the energy:
     * p_bar = -(energy(g1) - energy(g0)) / (g1 - g0), so that
     * p_bar (g1 - g0) is exactly the energy released; the midpoint pressure
     * where g1 - g0 is too small for the quotient.
     */
    virtual double
    discrete_gradient_pressure(double g0, double g1) const;
    /// d p_bar / d g1.
    virtual double
    discrete_gradient_derivative(double g0, double g1) const;
  };

  /// The registry of contact laws, by name.
  namespace ContactLaws
  {
    struct Entry
    {
      std::string                                     name;
      std::string                                     description;
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      std::function<std::unique_ptr<ContactLaw>()>    create;
    };

    /// Add a law (DISKIMPACT_REGISTER_CONTACT_LAW does it).
    bool
    add(const Entry &entry);
    /// The laws registered, sorted by name.
    std::vector<Entry>
    all();
    /// A new, unparsed law named @p name; an InputError if there is none.
    std::unique_ptr<ContactLaw>
    create(const std::string &name);
  } // namespace ContactLaws
} // namespace DiskImpact

/// Register @p Class as the contact law 'Law = @p name'.
#define DISKIMPACT_REGISTER_CONTACT_LAW(Class, name, description)   \
  namespace                                                         \
  {                                                                 \
    const bool Class##_registered = ::DiskImpact::ContactLaws::add( \
      {name, description, &Class::declare_parameters, []() {        \
         return std::unique_ptr<::DiskImpact::ContactLaw>(          \
           std::make_unique<Class>());                              \
       }});                                                         \
  }
