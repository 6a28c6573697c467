#include "contact.h"

#include "geometry.h"
#include "input_error.h"

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    Tensor<1, 2>
    parse_vector(const std::string &text, const std::string &entry)
    {
      const auto values =
        Utilities::string_to_double(Utilities::split_string_list(text, ','));
      require(values.size() == 2,
              "Contact: '" + entry + "' needs two components, got '" + text +
                "'");
      return Tensor<1, 2>({values[0], values[1]});
    }
  } // namespace

  double
  RigidWall::gap(const Point<2> &x) const
  {
    return (x - point) * normal;
  }

  double
  PenaltyLaw::pressure(const double gap) const
  {
    return gap < 0. ? -stiffness * gap : 0.;
  }

  double
  PenaltyLaw::pressure_derivative(const double gap) const
  {
    return gap < 0. ? -stiffness : 0.;
  }

  double
  PenaltyLaw::energy(const double gap) const
  {
    return gap < 0. ? 0.5 * stiffness * gap * gap : 0.;
  }

  double
  PenaltyLaw::discrete_gradient_pressure(const double g0, const double g1) const
  {
    const double dg = g1 - g0;
    // Below this the quotient loses digits; energy is quadratic, so the
    // midpoint pressure is then exact to rounding.
    if (std::abs(dg) <= 1e-10 * (std::abs(g0) + std::abs(g1)))
      return pressure(0.5 * (g0 + g1));
    return -(energy(g1) - energy(g0)) / dg;
  }

  double
  PenaltyLaw::discrete_gradient_derivative(const double g0,
                                           const double g1) const
  {
    const double dg = g1 - g0;
    if (std::abs(dg) <= 1e-10 * (std::abs(g0) + std::abs(g1)))
      return 0.5 * pressure_derivative(0.5 * (g0 + g1));
    // d/dg1 of -(E(g1) - E(g0)) / (g1 - g0), with E'(g) = -p(g)
    return (pressure(g1) * dg + (energy(g1) - energy(g0))) / (dg * dg);
  }

  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Penalty factor",
                      "100",
                      Patterns::Double(),
                      "Dimensionless penalty factor kappa > 0: the wall's "
                      "penalty stiffness is k = kappa E2 / h_contact [force / "
                      "length^3], with h_contact the length of the smallest "
                      "edge face at the contact point. The penalty error "
                      "(penetration) is proportional to 1 / kappa.");
    prm.declare_entry("Wall point",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 2),
                      "A point on the rigid wall [length]. The default wall "
                      "x = 0 touches the undeformed disk at the contact "
                      "point (0, 0).");
    prm.declare_entry("Wall normal",
                      "1, 0",
                      Patterns::List(Patterns::Double(), 2, 2),
                      "Normal of the wall pointing toward the disk [-] "
                      "(normalized on input).");
    prm.leave_subsection();
  }

  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    kappa = prm.get_double("Penalty factor");
    rigid_wall.point =
      Point<2>(parse_vector(prm.get("Wall point"), "Wall point"));
    const Tensor<1, 2> normal =
      parse_vector(prm.get("Wall normal"), "Wall normal");
    prm.leave_subsection();

    require(kappa > 0.,
            "Contact: 'Penalty factor' must be positive, got " +
              Utilities::to_string(kappa));
    require(normal.norm() > 0., "Contact: 'Wall normal' must not be zero");
    rigid_wall.normal = normal / normal.norm();
  }

  double
  ContactParameters::penalty_factor() const
  {
    return kappa;
  }

  void
  ContactParameters::set_penalty_factor(const double k)
  {
    kappa = k;
  }

  const RigidWall &
  ContactParameters::wall() const
  {
    return rigid_wall;
  }

  PenaltyLaw
  ContactParameters::penalty_law(const double in_plane_young_modulus,
                                 const double h_contact) const
  {
    return PenaltyLaw{kappa * in_plane_young_modulus / h_contact};
  }

  void
  ContactParameters::check_wall(const DiskGeometry &geometry,
                                const double        max_gap) const
  {
    const double R = geometry.radius();
    // Distance of the disk's closest point to the wall plane.
    const double gap = rigid_wall.gap(geometry.center()) - R;
    require(rigid_wall.gap(geometry.center()) > 0.,
            "Contact: the disk's centre lies behind the wall (the wall "
            "normal must point toward the disk)");
    require(gap > -1e-8 * R && gap <= max_gap * R + 1e-8 * R,
            "Contact: the wall misses the disk: the undeformed disk's gap to "
            "the wall is " +
              Utilities::to_string(gap) + " (must lie in [0, " +
              Utilities::to_string(max_gap * R) + "])");
    if (geometry.is_half_disk())
      require(std::abs(rigid_wall.normal[1]) < 1e-12,
              "Contact: a half disk (symmetric about y = 0) needs a wall "
              "normal along the x axis");
  }
} // namespace DiskImpact
