#include "contact/contact.h"

#include "base/input_error.h"
#include "body/geometry.h"

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
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

  template <int dim>
  std::array<Tensor<1, dim>, dim - 1>
  RigidWall<dim>::tangents() const
  {
    std::array<Tensor<1, dim>, dim - 1> t;
    t[0][0] = -normal[1];
    t[0][1] = normal[0];
    if constexpr (dim == 3)
      t[1] = cross_product_3d(normal, t[0]);
    return t;
  }

  template <int dim>
  template <int spacedim>
  RigidWall<spacedim>
  RigidWall<dim>::embedded() const
  {
    RigidWall<spacedim> wall;
    for (int d = 0; d < std::min(dim, spacedim); ++d)
      {
        wall.point[d]  = point[d];
        wall.normal[d] = normal[d];
      }
    return wall;
  }

  template struct RigidWall<2>;
  template struct RigidWall<3>;
  template RigidWall<2>
  RigidWall<2>::embedded<2>() const;
  template RigidWall<3>
  RigidWall<2>::embedded<3>() const;

  ContactParameters::ContactParameters()
      : parsed_law(ContactLaws::create("penalty"))
  {
  }

  ContactParameters::ContactParameters(const ContactParameters &other)
      : name(other.name)
      , friction(other.friction)
      , parsed_law(other.parsed_law->clone())
      , rigid_wall(other.rigid_wall)
  {
  }

  ContactParameters &
  ContactParameters::operator=(const ContactParameters &other)
  {
    name       = other.name;
    friction   = other.friction;
    parsed_law = other.parsed_law->clone();
    rigid_wall = other.rigid_wall;
    return *this;
  }

  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    std::string names, laws;
    for (const auto &law : ContactLaws::all())
      {
        names += law.name + "|";
        laws += "'" + law.name + "', " + law.description + "; ";
        law.declare_parameters(prm);
      }
    prm.declare_entry(
      "Law",
      "penalty",
      Patterns::Selection(names + "constraint"),
      "The wall's pressure p on an edge point with gap g: " + laws +
        "'constraint', no penetration at the edge nodes (g >= 0 exactly, the "
        "pressure a Lagrange multiplier; the contact zone's edge carries no "
        "mass, docs/theory/impact-method.md).");
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
    prm.declare_entry(
      "Friction coefficient",
      "0",
      Patterns::Double(0.),
      "Coulomb's friction coefficient mu of the wall [-]: the tangential "
      "traction of an edge point is at most mu times its pressure; below "
      "that the point sticks, elastically with the law's stiffness "
      "(docs/theory/friction.md). 0: frictionless. Needs 'Law = penalty'.");
    prm.leave_subsection();
  }

  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    name = prm.get("Law");
    // Every law's entries are checked, the chosen one's are kept.
    for (const auto &law : ContactLaws::all())
      {
        auto parsed = law.create();
        parsed->parse_parameters(prm);
        if (law.name == name)
          parsed_law = std::move(parsed);
      }
    friction = prm.get_double("Friction coefficient");
    rigid_wall.point =
      Point<2>(parse_vector(prm.get("Wall point"), "Wall point"));
    const Tensor<1, 2> normal =
      parse_vector(prm.get("Wall normal"), "Wall normal");
    prm.leave_subsection();
    require(normal.norm() > 0., "Contact: 'Wall normal' must not be zero");
    rigid_wall.normal = normal / normal.norm();
    require(friction == 0. ||
              (!exact_constraint() && parsed_law->supports_friction()),
            "Contact: 'Friction coefficient' > 0 needs 'Law = penalty' (the "
            "law '" +
              name + "' has no stick stiffness)");
  }

  template <int dim>
  RigidWall<dim>
  ContactParameters::wall() const
  {
    return rigid_wall.embedded<dim>();
  }

  template RigidWall<2>
  ContactParameters::wall<2>() const;
  template RigidWall<3>
  ContactParameters::wall<3>() const;

  const std::string &
  ContactParameters::law_name() const
  {
    return name;
  }

  bool
  ContactParameters::exact_constraint() const
  {
    return name == "constraint";
  }

  std::shared_ptr<const ContactLaw>
  ContactParameters::law(const ContactScales &scales) const
  {
    if (exact_constraint())
      return nullptr;
    std::shared_ptr<ContactLaw> law = parsed_law->clone();
    law->set_scales(scales);
    return law;
  }

  const ContactLaw &
  ContactParameters::parsed() const
  {
    return *parsed_law;
  }

  void
  ContactParameters::stiffen_law(const double factor)
  {
    parsed_law->stiffen(factor);
  }

  bool
  ContactParameters::approximates_hard_contact() const
  {
    return exact_constraint() || parsed_law->approximates_hard_contact();
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
    if (geometry.has_symmetry_boundary())
      require(std::abs(rigid_wall.normal[1]) < 1e-12,
              "Contact: a half disk (symmetric about y = 0) needs a wall "
              "normal along the x axis");
  }
} // namespace DiskImpact
