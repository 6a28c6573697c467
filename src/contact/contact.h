#pragma once

#include "contact/contact_law.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <memory>
#include <string>

namespace DiskImpact
{
  class BodyGeometry;

  /**
   * A rigid plane wall: a point on it and its unit normal, pointing from the
   * wall toward the body. The gap of a point x is g = (x - point) . normal;
   * g < 0 is penetration. In three dimensions it is the plane wall of the
   * two-dimensional model extended along z (embedded()).
   */
  template <int dim>
  struct RigidWall
  {
    dealii::Point<dim>     point;
    dealii::Tensor<1, dim> normal;

    double
    gap(const dealii::Point<dim> &x) const
    {
      return (x - point) * normal;
    }

    /// An orthonormal basis of the wall's plane: in two dimensions the
    /// tangent (-n_y, n_x), in three also e_z (the wall contains z).
    std::array<dealii::Tensor<1, dim>, dim - 1>
    tangents() const;

    /// The same wall in @p spacedim dimensions: point and normal with zero
    /// components beyond the plane's.
    template <int spacedim>
    RigidWall<spacedim>
    embedded() const;
  };

  /**
   * Subsection "Contact": the wall and how it acts: 'Law' names a
   * registered ContactLaw (ContactLaws) or 'constraint', the exact
   * non-penetration g >= 0 at the edge nodes, whose pressure is a Lagrange
   * multiplier (ContactStepper solves for it). Each law declares and parses
   * its own entries.
   */
  class ContactParameters
  {
  public:
    ContactParameters();
    ContactParameters(const ContactParameters &other);
    ContactParameters &
    operator=(const ContactParameters &other);

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The wall, in the plane model's two dimensions or (@p dim = 3)
    /// extended along z.
    template <int dim = 2>
    RigidWall<dim>
    wall() const;
    /// The 'Law' entry: a law's name or 'constraint'.
    const std::string &
    law_name() const;
    /// Whether 'Law = constraint'.
    bool
    exact_constraint() const;
    /// 'Friction coefficient': Coulomb's mu of the wall (0: frictionless).
    double
    friction_coefficient() const
    {
      return friction;
    }

    /// The chosen law for the pair's in-plane modulus E2, contact element
    /// size h and radius R (null with the exact constraint).
    std::shared_ptr<const ContactLaw>
    law(const ContactScales &scales) const;
    /// The chosen law made @p factor times stiffer where it regularizes
    /// hard contact (ContactLaw::stiffen()).
    void
    stiffen_law(double factor);
    /// The chosen law as parsed, unscaled (not for 'Law = constraint').
    const ContactLaw &
    parsed() const;
    /// Whether the law approximates hard contact (so does the constraint).
    bool
    approximates_hard_contact() const;

    /**
     * Check that the wall touches the undeformed disk (within
     * @p gap_tolerance R, positive gap allowed up to @p max_gap R) with the
     * disk on the side its normal points to, and that a half disk's wall is
     * perpendicular to the symmetry axis.
     */
    void
    check_wall(const BodyGeometry &geometry, double max_gap) const;

  private:
    std::string                 name     = "penalty";
    double                      friction = 0.;
    std::unique_ptr<ContactLaw> parsed_law;
    RigidWall<2>                rigid_wall;
  };
} // namespace DiskImpact
