#include "contact/contact.h"

#include "base/input_error.h"
#include "body/geometry.h"

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <utility>

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

  namespace
  {
    /// p_c / E2 of the exponential law: below it the pressure is dropped.
    constexpr double exponential_cut = 1e-16;

    /// phi(x) = (1 - e^{-x}) / x and phi'(x), accurate near x = 0.
    std::pair<double, double>
    relative_secant(const double x)
    {
      if (std::abs(x) < 1e-3)
        return {1. - x / 2. + x * x / 6. - x * x * x / 24.,
                -0.5 + x / 3. - x * x / 8. + x * x * x / 30.};
      const double e = std::exp(-x);
      return {-std::expm1(-x) / x, ((1. + x) * e - 1.) / (x * x)};
    }
  } // namespace

  double
  WallLaw::pressure(const double gap) const
  {
    if (!(gap < 0.) || kind == WallLawKind::constraint)
      return 0.;
    return kind == WallLawKind::penalty ? -stiffness * gap :
                                          threshold * std::exp(-decay * gap);
  }

  double
  WallLaw::pressure_derivative(const double gap) const
  {
    if (!(gap < 0.) || kind == WallLawKind::constraint)
      return 0.;
    return kind == WallLawKind::penalty ? -stiffness : -decay * pressure(gap);
  }

  double
  WallLaw::energy(const double gap) const
  {
    if (!(gap < 0.) || kind == WallLawKind::constraint)
      return 0.;
    return kind == WallLawKind::penalty ?
             0.5 * stiffness * gap * gap :
             threshold / decay * std::expm1(-decay * gap);
  }

  double
  WallLaw::reach() const
  {
    return kind == WallLawKind::exponential ?
             -std::log(exponential_cut) / decay :
             0.;
  }

  double
  WallLaw::discrete_gradient_pressure(const double g0, const double g1) const
  {
    const double dg = g1 - g0;
    // Both in the exponential's range: p(g0) phi(lambda dg) without
    // cancellation.
    if (kind == WallLawKind::exponential && g0 < 0. && g1 < 0.)
      return pressure(g0) * relative_secant(decay * dg).first;
    // Below this the quotient loses digits; the penalty energy is
    // quadratic, so the midpoint pressure is then exact to rounding.
    if (std::abs(dg) <= 1e-10 * (std::abs(g0) + std::abs(g1)))
      return pressure(0.5 * (g0 + g1));
    return -(energy(g1) - energy(g0)) / dg;
  }

  double
  WallLaw::discrete_gradient_derivative(const double g0, const double g1) const
  {
    const double dg = g1 - g0;
    if (kind == WallLawKind::exponential && g0 < 0. && g1 < 0.)
      return pressure(g0) * decay * relative_secant(decay * dg).second;
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
    prm.declare_entry(
      "Law",
      "penalty",
      Patterns::Selection("penalty|exponential|constraint"),
      "The wall's pressure p on an edge point with gap g: "
      "'penalty', p = k <-g>; 'exponential', the smooth wall "
      "potential of Gerl & Zippelius 1999 (eq. 41), energy (E2 R / s) "
      "exp(s x / R) per unit edge length, s the 'Potential stiffness' "
      "and x the distance "
      "of the point beyond the wall plane, cut where the "
      "pressure falls below 1e-16 E2 (the disk starts that "
      "far from the wall, 36.8 R / s); 'constraint', no "
      "penetration at the edge nodes (g >= 0 exactly, the "
      "pressure a Lagrange multiplier; the contact zone's "
      "edge carries no mass, docs/theory/impact-method.md).");
    prm.declare_entry("Potential stiffness",
                      "100",
                      Patterns::Double(),
                      "Law 'exponential': the stiffness s > 0 of the "
                      "potential [-] (Gerl & Zippelius' alpha; hard contact "
                      "as s -> infinity).");
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
    kappa                      = prm.get_double("Penalty factor");
    const std::string law_name = prm.get("Law");
    kind  = law_name == "exponential" ? WallLawKind::exponential :
            law_name == "constraint"  ? WallLawKind::constraint :
                                        WallLawKind::penalty;
    alpha = prm.get_double("Potential stiffness");
    rigid_wall.point =
      Point<2>(parse_vector(prm.get("Wall point"), "Wall point"));
    const Tensor<1, 2> normal =
      parse_vector(prm.get("Wall normal"), "Wall normal");
    prm.leave_subsection();

    require(kappa > 0.,
            "Contact: 'Penalty factor' must be positive, got " +
              Utilities::to_string(kappa));
    require(alpha > 0.,
            "Contact: 'Potential stiffness' must be positive, got " +
              Utilities::to_string(alpha));
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

  WallLaw
  ContactParameters::penalty_law(const double in_plane_young_modulus,
                                 const double h_contact) const
  {
    WallLaw law;
    law.stiffness = kappa * in_plane_young_modulus / h_contact;
    return law;
  }

  WallLawKind
  ContactParameters::law_kind() const
  {
    return kind;
  }

  WallLaw
  ContactParameters::wall_law(const double in_plane_young_modulus,
                              const double h_contact,
                              const double radius) const
  {
    if (kind == WallLawKind::penalty)
      return penalty_law(in_plane_young_modulus, h_contact);
    WallLaw law;
    law.kind = kind;
    if (kind == WallLawKind::constraint)
      return law;
    law.decay     = alpha / radius;
    law.threshold = exponential_cut * in_plane_young_modulus;
    return law;
  }

  void
  ContactParameters::check_wall(const BodyGeometry &geometry,
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
