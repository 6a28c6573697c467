#include "contact/penalty_law.h"

#include "base/input_error.h"

#include <deal.II/base/utilities.h>

namespace DiskImpact
{
  using namespace dealii;

  DISKIMPACT_REGISTER_CONTACT_LAW(PenaltyLaw,
                                  "penalty",
                                  "p = k <-g> with k = kappa E2 / h (the "
                                  "'Penalty factor' kappa)")

  void
  PenaltyLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Penalty factor",
                      "100",
                      Patterns::Double(),
                      "Dimensionless penalty factor kappa > 0: the wall's "
                      "penalty stiffness is k = kappa E2 / h_contact [force / "
                      "length^3], with h_contact the length of the smallest "
                      "edge face at the contact point (in 3D: the square "
                      "root of a sphere's face area; for a disk, the face's "
                      "edge in the section, as in 2D). The penalty error "
                      "(penetration) is proportional to 1 / kappa.");
  }

  void
  PenaltyLaw::parse_parameters(ParameterHandler &prm)
  {
    kappa = prm.get_double("Penalty factor");
    require(kappa > 0.,
            "Contact: 'Penalty factor' must be positive, got " +
              Utilities::to_string(kappa));
  }

  std::unique_ptr<ContactLaw>
  PenaltyLaw::clone() const
  {
    return std::make_unique<PenaltyLaw>(*this);
  }

  void
  PenaltyLaw::set_scales(const ContactScales &scales)
  {
    k = kappa * scales.modulus / scales.element_size;
  }

  void
  PenaltyLaw::stiffen(const double factor)
  {
    kappa *= factor;
  }

  double
  PenaltyLaw::pressure(const double gap) const
  {
    return gap < 0. ? -k * gap : 0.;
  }

  double
  PenaltyLaw::pressure_derivative(const double gap) const
  {
    return gap < 0. ? -k : 0.;
  }

  double
  PenaltyLaw::energy(const double gap) const
  {
    return gap < 0. ? 0.5 * k * gap * gap : 0.;
  }

  double
  PenaltyLaw::tangential_stiffness() const
  {
    return k;
  }

  bool
  PenaltyLaw::supports_friction() const
  {
    return true;
  }

  double
  PenaltyLaw::penalty_factor() const
  {
    return kappa;
  }

} // namespace DiskImpact
