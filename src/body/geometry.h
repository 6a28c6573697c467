#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <limits>
#include <string>

namespace DiskImpact
{
  /**
   * Boundary ids of the disk (built-in meshes and meshes/disk.geo alike):
   * the curved edge (free, or in contact with the wall) and the diameter on
   * the impact axis (half disk only, symmetry: u_y = 0). A quarter sphere
   * in 3D has the symmetry planes y = 0 (symmetry) and z = 0 (symmetry_z,
   * u_z = 0).
   */
  namespace BoundaryIds
  {
    constexpr dealii::types::boundary_id curved   = 1;
    constexpr dealii::types::boundary_id symmetry = 2;
    /// The curved edge of a collision partner (class Partner).
    constexpr dealii::types::boundary_id partner_curved = 3;
    constexpr dealii::types::boundary_id symmetry_z     = 4;
    /// The flat faces z = +-H/2 of a disk in 3D (u_z = 0 if held).
    constexpr dealii::types::boundary_id flat_faces = 5;
  } // namespace BoundaryIds

  /// The point @p x of the plane models in @p dim dimensions (z = 0).
  template <int dim>
  dealii::Point<dim>
  embedded(const dealii::Point<2> &x)
  {
    dealii::Point<dim> y;
    y[0] = x[0];
    y[1] = x[1];
    return y;
  }

  /// Manifold id of the curved edge.
  constexpr dealii::types::manifold_id curved_manifold_id = 1;
  /// Manifold id of a collision partner's curved edge.
  constexpr dealii::types::manifold_id partner_manifold_id = 2;

  /// Call @p f(cell, face_number) for every face on the curved edge of the
  /// locally owned cells of @p dof_handler.
  template <int dim, typename Function>
  void
  for_each_curved_edge_face(const dealii::DoFHandler<dim> &dof_handler,
                            Function                     &&f)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto face : cell->face_indices())
          if (cell->face(face)->at_boundary() &&
              cell->face(face)->boundary_id() == BoundaryIds::curved)
            f(cell, face);
  }

  /// Radius of the zone of finest elements around the contact point, in
  /// units of the contact half-width a, unless a task sets its own
  /// (subsection Impact, 'Fine zone radius').
  constexpr double default_fine_zone_radius = 1.5;

  /**
   * Refine toward @p contact_point until every cell closer than r a
   * (r = @p fine_zone_radius) has size <= a / n_across and, farther out,
   * size <= a / n_across + grading (d - r a), d the distance to the contact
   * point: with r >= 1 the elements across the whole contact zone of
   * half-width a, not only the smallest, resolve it. With a unit vector
   * @p contact_line d is the distance to the line through the contact
   * point along it (a disk's rim in 3D) and a cell's size is measured in
   * the section across the line, as in 2D. Throws an InputError if the mesh
   * would exceed @p max_cells active cells.
   */
  template <int dim>
  void
  refine_toward_contact(
    dealii::Triangulation<dim> &triangulation,
    const dealii::Point<dim>   &contact_point,
    double                      a,
    unsigned int                n_across,
    double                      grading,
    double                      fine_zone_radius,
    double max_cells = std::numeric_limits<double>::infinity(),
    const dealii::Tensor<1, dim> &contact_line = {});

  /// The body: a disk (plane strain or plane stress) or a sphere (an
  /// axisymmetric model on its meridian).
  enum class Body
  {
    disk,
    sphere
  };

  std::string
  to_string(Body body);

  /**
   * The body's two-dimensional domain: radius, full or half domain, built-in or
   * gmsh mesh, global refinement and graded refinement toward the contact
   * point.
   *
   * The disk's centre is (R, 0), so the undeformed disk touches the plane
   * x = 0 at the contact point (0, 0); the impact axis is y = 0 and the
   * half disk is y >= 0.
   *
   * A sphere is the same half disk read as its meridian: x is the axial
   * coordinate z, y the distance r from the symmetry (impact) axis, and the
   * symmetry line y = 0 is the axis, where u_r = u_y = 0. The meridian
   * holds both hemispheres (no mirror symmetry about the equator).
   */
  class BodyGeometry
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse subsection Geometry; an empty 'Domain' of a disk is a half
    /// disk if @p half_disk_by_default, else a full disk.
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     bool                      half_disk_by_default = false);

    double
    radius() const;
    /// 'Dimension': 2 (a plane model or the sphere's meridian) or 3 (the
    /// body itself, create_solid_triangulation()).
    unsigned int
    dimension() const;
    Body
    body() const;
    /// Whether the body is a sphere (on its meridian or in 3D).
    bool
    is_sphere() const;
    /// Whether the model is the sphere's meridian (axisymmetric).
    bool
    is_axisymmetric() const;
    /// Whether the domain is y >= 0 only and ends on the impact axis y = 0
    /// (boundary id BoundaryIds::symmetry, u_y = 0 there): a half disk's
    /// mirror line, a sphere meridian's axis; in 3D the quarter sphere
    /// y >= 0, z >= 0 (also BoundaryIds::symmetry_z, u_z = 0 on z = 0).
    bool
    has_symmetry_boundary() const;
    /// Whether the model can move along the wall and turn about e_z: the
    /// whole disk in two dimensions, the whole or half sphere in three
    /// (whose plane of incidence is z = 0).
    bool
    turns_in_plane() const;
    /// In 3D, whether the domain is z >= 0 only and ends on the plane z = 0
    /// (boundary id BoundaryIds::symmetry_z, u_z = 0 there): the quarter
    /// and the half sphere, the quarter of a disk.
    bool
    has_symmetry_plane_z() const;
    /// The share of the body's loads the computed domain carries: 1/2 for
    /// a half disk or a half sphere, 1/4 for a quarter sphere, 1 for a full
    /// disk or a sphere (whose meridian's integrals are over the whole sphere).
    /// A disk's loads are per unit thickness: a disk of thickness H in 3D
    /// carries H (H/4 its quarter).
    double
    domain_share() const;
    /// A disk in 3D: its thickness H.
    double
    thickness() const;
    /// A disk in 3D: whether its flat faces are held at u_z = 0 (which
    /// makes it the plane-strain disk exactly).
    bool
    faces_held() const;
    /// The body's volume: pi R^2 for a disk (per unit thickness), 4 pi R^3
    /// / 3 for a sphere.
    double
    volume() const;
    dealii::Point<2>
    center() const;
    dealii::Point<2>
    contact_point() const;
    unsigned int
    global_refinements() const;
    void
    set_global_refinements(unsigned int n);

    /// Build the coarse mesh, attach the manifold and refine; throws an
    /// InputError if the refined mesh would exceed about @p max_cells cells.
    void
    create_triangulation(
      dealii::Triangulation<2> &triangulation,
      double max_cells = std::numeric_limits<double>::infinity()) const;

    /**
     * The coarse mesh alone (built in, or read from 'Mesh file'), with its
     * boundary and manifold ids; throws an InputError for a mesh that is
     * not a disk of this radius and domain made of quadrilaterals.
     */
    void
    create_coarse_triangulation(dealii::Triangulation<2> &triangulation) const;

    /// The global refinements and the contact refinements toward the
    /// origin of create_triangulation(), on a coarse mesh; throws an
    /// InputError if they would exceed about @p max_cells cells.
    void
    refine(dealii::Triangulation<2> &triangulation,
           double max_cells = std::numeric_limits<double>::infinity()) const;

    /// The same geometry with radius @p radius (a collision partner's).
    BodyGeometry
    with_radius(double radius) const;

    /// Whether the coarse mesh is read from 'Mesh file'.
    bool
    has_mesh_file() const;

    /// One line describing the mesh source and refinement.
    std::string
    description() const;

  private:
    void
    create_builtin_coarse_mesh(dealii::Triangulation<2> &triangulation) const;
    void
    read_coarse_mesh(dealii::Triangulation<2> &triangulation) const;
    void
    set_boundary_and_manifold_ids(
      dealii::Triangulation<2> &triangulation) const;
    void
    refine_toward_contact_point(dealii::Triangulation<2> &triangulation) const;

    Body         body_kind         = Body::disk;
    unsigned int space_dimension   = 2;
    double       disk_thickness    = 1.;
    bool         held_faces        = false;
    double       body_radius       = 1.;
    bool         symmetry_boundary = false;
    bool         symmetry_plane_z  = false;
    std::string  mesh_file;
    unsigned int n_global_refinements  = 3;
    unsigned int n_contact_refinements = 0;
  };
} // namespace DiskImpact
