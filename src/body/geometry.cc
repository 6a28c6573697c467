#include "body/geometry.h"

#include "base/input_error.h"

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace DiskImpact
{
  using namespace dealii;

  template <int dim>
  void
  refine_toward_contact(Triangulation<dim>   &triangulation,
                        const Point<dim>     &contact_point,
                        const double          a,
                        const unsigned int    n_across,
                        const double          grading,
                        const double          fine_zone_radius,
                        const double          max_cells,
                        const Tensor<1, dim> &contact_line)
  {
    const auto distance = [&](const Point<dim> &x) {
      const Tensor<1, dim> r = x - contact_point;
      return (r - (r * contact_line) * contact_line).norm();
    };
    // A cell's size: its diameter over sqrt(dim), or, along a contact
    // line, its diameter in the section across the line (an extruded
    // cell's size as in 2D, whatever its extent along the line).
    const bool along_line = contact_line.norm_square() > 0.;
    const auto size       = [&](const auto &cell) {
      if (!along_line)
        return cell->diameter() / std::sqrt(double(dim));
      double         diameter = 0.;
      const unsigned last     = cell->n_vertices() - 1;
      for (unsigned int v = 0; v < cell->n_vertices() / 2; ++v)
        {
          const Tensor<1, dim> r = cell->vertex(v) - cell->vertex(last - v);
          diameter =
            std::max(diameter, (r - (r * contact_line) * contact_line).norm());
        }
      return diameter / std::sqrt(double(dim - 1));
    };
    const double h_min = a / n_across;
    for (unsigned int step = 0; step < 60; ++step)
      {
        require(triangulation.n_global_active_cells() <= max_cells,
                "the mesh graded toward the contact point (" +
                  std::to_string(n_across) +
                  " elements across the contact, grading " +
                  Utilities::to_string(grading) + ") would exceed " +
                  approximately(max_cells) +
                  " cells, more than this machine's memory holds");
        bool any = false;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const double h = size(cell);
              const double d = std::max(0., distance(cell->center()) - h);
              const double target =
                h_min + grading * std::max(0., d - fine_zone_radius * a);
              if (h > target)
                {
                  cell->set_refine_flag();
                  any = true;
                }
            }
        if (!Utilities::MPI::logical_or(any, triangulation.get_communicator()))
          return;
        triangulation.execute_coarsening_and_refinement();
      }
  }

  template void
  refine_toward_contact(Triangulation<2> &,
                        const Point<2> &,
                        double,
                        unsigned int,
                        double,
                        double,
                        double,
                        const Tensor<1, 2> &);
  template void
  refine_toward_contact(Triangulation<3> &,
                        const Point<3> &,
                        double,
                        unsigned int,
                        double,
                        double,
                        double,
                        const Tensor<1, 3> &);

  std::string
  to_string(const Body body)
  {
    return body == Body::sphere ? "sphere" : "disk";
  }

  void
  BodyGeometry::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Body",
                        "disk",
                        Patterns::Selection("disk|sphere"),
                        "'disk' (a plane model, 'Plane model' in subsection "
                        "Material), or 'sphere': the axisymmetric model on "
                        "the meridian half disk y >= 0 (x along the impact "
                        "axis, y = r the distance from it), which takes no "
                        "'Domain' and no 'Plane model'.");
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "2: the disk in a plane model, or the sphere's "
                        "meridian (axisymmetric). 3: the body itself in "
                        "three dimensions, for the tasks 'modal analysis', "
                        "'impact', 'impact convergence' and 'sweep': the "
                        "sphere ('Domain' full, half or quarter sphere) or "
                        "the disk of 'Thickness' H ('Domain' full or half "
                        "disk, the half also halved in thickness); the "
                        "built-in mesh only (no 'Mesh file' or 'Contact "
                        "refinements').");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(),
                        "Disk radius R [length]. Must be positive. The disk's "
                        "centre is at (R, 0): it touches the plane x = 0 at "
                        "the origin.");
      prm.declare_entry(
        "Domain",
        "",
        Patterns::Selection(
          "|full disk|half disk|full sphere|half sphere|quarter sphere"),
        "Disks: 'half disk' (y >= 0, symmetric about "
        "the impact axis y = 0: exact for a head-on impact; "
        "only modes even about the axis) or 'full disk'. "
        "Empty: 'full disk' for the tasks 'modal analysis' "
        "and 'modal convergence', 'half disk' for the "
        "others; a disk in 3D's half is also halved in "
        "thickness (0 <= z <= H/2, symmetric about z = 0: "
        "its modes are the in-plane ones even about y = 0). "
        "The sphere in 3D: 'quarter sphere' (y >= 0, "
        "z >= 0, symmetric about the planes y = 0 and z = 0: "
        "exact for a head-on impact), 'half sphere' (z >= 0, "
        "symmetric about the plane of incidence z = 0: "
        "exact for an oblique impact) or 'full sphere'; "
        "empty: the full sphere for the modal tasks, the "
        "quarter for the others (a modal analysis takes "
        "the full sphere). Must be empty for a "
        "sphere in 2D, whose domain is its meridian.");
      prm.declare_entry("Thickness",
                        "1",
                        Patterns::Double(),
                        "A disk in 3D ('Dimension = 3'): its thickness H "
                        "along z [length], the disk -H/2 <= z <= H/2 (an "
                        "impact computes the quarter y >= 0, 0 <= z <= H/2). "
                        "Must be positive.");
      prm.declare_entry("Faces",
                        "free",
                        Patterns::Selection("free|held"),
                        "A disk in 3D: its flat faces z = +-H/2 free, or "
                        "held at u_z = 0, which makes it exactly the "
                        "plane-strain disk.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "Empty: the built-in mesh (balanced ball). Otherwise "
                        "a gmsh .msh file (see meshes/disk.geo) with boundary "
                        "id 1 on the curved edge and 2 on the symmetry line; "
                        "it must match 'Radius' and 'Domain'.");
      prm.declare_entry("Global refinements",
                        "3",
                        Patterns::Integer(0, 12),
                        "Number of uniform refinements of the coarse mesh.");
      prm.declare_entry("Contact refinements",
                        "0",
                        Patterns::Integer(0, 20),
                        "Extra refinement steps toward the contact point "
                        "(0, 0): step i refines the cells closer than "
                        "R / 2^i to it.");
    }
    prm.leave_subsection();
  }

  void
  BodyGeometry::parse_parameters(ParameterHandler &prm,
                                 const bool        half_disk_by_default)
  {
    prm.enter_subsection("Geometry");
    body_kind       = prm.get("Body") == "sphere" ? Body::sphere : Body::disk;
    body_radius     = prm.get_double("Radius");
    space_dimension = prm.get_integer("Dimension");
    const std::string domain = prm.get("Domain");
    // A half disk (in 3D also halved in thickness) and a quarter sphere end
    // on planes of symmetry; a sphere's meridian always ends on its axis.
    symmetry_boundary = domain == "half disk" || domain == "quarter sphere" ||
                        (domain.empty() && half_disk_by_default) ||
                        (space_dimension == 2 && body_kind == Body::sphere);
    // The half sphere ends on the plane z = 0 only.
    symmetry_plane_z =
      space_dimension == 3 && (domain == "half sphere" ||
                               (symmetry_boundary && domain != "full sphere"));
    mesh_file             = prm.get("Mesh file");
    n_global_refinements  = prm.get_integer("Global refinements");
    n_contact_refinements = prm.get_integer("Contact refinements");
    disk_thickness        = prm.get_double("Thickness");
    held_faces            = prm.get("Faces") == "held";
    prm.leave_subsection();

    require(body_kind == Body::disk || domain.empty() ||
              (space_dimension == 3 &&
               domain.find("sphere") != std::string::npos),
            "Geometry: 'Domain = " + domain +
              "' is a disk entry; a sphere's domain is its meridian in 2D "
              "(remove 'Domain'), 'full sphere', 'half sphere' or 'quarter "
              "sphere' in 3D");
    require(body_kind == Body::sphere ||
              domain.find("sphere") == std::string::npos,
            "Geometry: 'Domain = " + domain + "' is a sphere's entry");
    require(space_dimension == 2 ||
              (mesh_file.empty() && n_contact_refinements == 0),
            "Geometry: 'Dimension = 3' takes the built-in mesh: no 'Mesh "
            "file' or 'Contact refinements'");
    require(space_dimension == 2 || body_kind == Body::sphere ||
              disk_thickness > 0.,
            "Geometry: 'Thickness' must be positive, got " +
              std::to_string(disk_thickness));
    require(body_radius > 0,
            "Geometry: 'Radius' must be positive, got " +
              std::to_string(body_radius));
    if (!mesh_file.empty())
      require(std::filesystem::is_regular_file(mesh_file),
              "Geometry: mesh file '" + mesh_file + "' " +
                (std::filesystem::is_directory(mesh_file) ? "is a directory" :
                                                            "does not exist"));
  }

  double
  BodyGeometry::radius() const
  {
    return body_radius;
  }

  unsigned int
  BodyGeometry::dimension() const
  {
    return space_dimension;
  }

  Body
  BodyGeometry::body() const
  {
    return body_kind;
  }

  bool
  BodyGeometry::is_sphere() const
  {
    return body_kind == Body::sphere;
  }

  bool
  BodyGeometry::is_axisymmetric() const
  {
    return body_kind == Body::sphere && space_dimension == 2;
  }

  bool
  BodyGeometry::has_symmetry_boundary() const
  {
    return symmetry_boundary;
  }

  bool
  BodyGeometry::turns_in_plane() const
  {
    if (symmetry_boundary)
      return false;
    return space_dimension == 2 ? body_kind == Body::disk :
                                  body_kind == Body::sphere;
  }

  bool
  BodyGeometry::has_symmetry_plane_z() const
  {
    return symmetry_plane_z;
  }

  double
  BodyGeometry::domain_share() const
  {
    if (space_dimension == 3 && body_kind == Body::disk)
      return symmetry_boundary ? 0.25 * disk_thickness : disk_thickness;
    if (space_dimension == 3)
      return (symmetry_boundary ? 0.5 : 1.) * (symmetry_plane_z ? 0.5 : 1.);
    if (!symmetry_boundary)
      return 1.;
    return body_kind == Body::sphere ? 1. : 0.5;
  }

  double
  BodyGeometry::volume() const
  {
    return body_kind == Body::sphere ?
             4. / 3. * M_PI * std::pow(body_radius, 3) :
             M_PI * body_radius * body_radius;
  }

  Point<2>
  BodyGeometry::center() const
  {
    return Point<2>(body_radius, 0.);
  }

  Point<2>
  BodyGeometry::contact_point() const
  {
    return Point<2>(0., 0.);
  }

  double
  BodyGeometry::thickness() const
  {
    return disk_thickness;
  }

  bool
  BodyGeometry::faces_held() const
  {
    return held_faces;
  }

  unsigned int
  BodyGeometry::global_refinements() const
  {
    return n_global_refinements;
  }

  void
  BodyGeometry::set_global_refinements(const unsigned int n)
  {
    n_global_refinements = n;
  }

  bool
  BodyGeometry::has_mesh_file() const
  {
    return !mesh_file.empty();
  }

  std::string
  BodyGeometry::description() const
  {
    if (space_dimension == 3 && body_kind == Body::disk)
      return std::string(symmetry_boundary ? "quarter of a disk" : "disk") +
             " in 3D, R = " + std::to_string(body_radius) +
             ", H = " + std::to_string(disk_thickness) + ", faces " +
             (held_faces ? "held (u_z = 0)" : "free") + ", built-in mesh, " +
             std::to_string(n_global_refinements) + " global refinements";
    if (space_dimension == 3)
      return std::string(symmetry_boundary ? "quarter sphere" :
                         symmetry_plane_z  ? "half sphere" :
                                             "sphere") +
             " in 3D, R = " + std::to_string(body_radius) +
             ", built-in mesh, " + std::to_string(n_global_refinements) +
             " global refinements";
    return std::string(body_kind == Body::sphere ? "sphere (meridian)" :
                       symmetry_boundary         ? "half disk" :
                                                   "full disk") +
           ", R = " + std::to_string(body_radius) + ", " +
           (mesh_file.empty() ? "built-in mesh" : "mesh file " + mesh_file) +
           ", " + std::to_string(n_global_refinements) +
           " global refinements, " + std::to_string(n_contact_refinements) +
           " contact refinements";
  }

  void
  BodyGeometry::create_triangulation(Triangulation<2> &triangulation,
                                     const double      max_cells) const
  {
    create_coarse_triangulation(triangulation);
    refine(triangulation, max_cells);
  }

  void
  BodyGeometry::refine(Triangulation<2> &triangulation,
                       const double      max_cells) const
  {
    // Each global refinement quadruples the cells, each contact refinement
    // adds about as many as the uniform mesh has.
    const double n_cells = triangulation.n_global_active_cells() *
                           std::pow(4., n_global_refinements) *
                           (1. + n_contact_refinements);
    require(n_cells <= max_cells,
            "Geometry: 'Global refinements = " +
              std::to_string(n_global_refinements) + "' (with " +
              std::to_string(n_contact_refinements) +
              " contact refinements) gives about " + approximately(n_cells) +
              " cells, more than the " + approximately(max_cells) +
              " this machine's memory holds");
    triangulation.refine_global(n_global_refinements);
    refine_toward_contact_point(triangulation);
  }

  BodyGeometry
  BodyGeometry::with_radius(const double radius) const
  {
    BodyGeometry copy = *this;
    copy.body_radius  = radius;
    return copy;
  }

  void
  BodyGeometry::create_coarse_triangulation(
    Triangulation<2> &triangulation) const
  {
    if (mesh_file.empty())
      create_builtin_coarse_mesh(triangulation);
    else
      read_coarse_mesh(triangulation);
    set_boundary_and_manifold_ids(triangulation);
    triangulation.set_manifold(curved_manifold_id,
                               SphericalManifold<2>(center()));
  }

  void
  BodyGeometry::create_builtin_coarse_mesh(
    Triangulation<2> &triangulation) const
  {
    if (!symmetry_boundary)
      {
        GridGenerator::hyper_ball_balanced(triangulation,
                                           center(),
                                           body_radius);
        return;
      }
    // The balanced ball has cell edges on the diameter y = 0: drop the
    // lower half.
    Triangulation<2> full;
    GridGenerator::hyper_ball_balanced(full, center(), body_radius);
    std::set<Triangulation<2>::active_cell_iterator> lower_half;
    for (const auto &cell : full.active_cell_iterators())
      if (cell->center()[1] < 0.)
        lower_half.insert(cell);
    GridGenerator::create_triangulation_with_removed_cells(full,
                                                           lower_half,
                                                           triangulation);
  }

  void
  BodyGeometry::read_coarse_mesh(Triangulation<2> &triangulation) const
  {
    std::ifstream in(mesh_file);
    require(static_cast<bool>(in),
            "Geometry: cannot open mesh file '" + mesh_file + "'");
    GridIn<2> grid_in;
    grid_in.attach_triangulation(triangulation);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const std::exception &e)
      {
        throw InputError("Geometry: cannot read gmsh file '" + mesh_file +
                         "' (a 2D quadrilateral mesh in msh format 2.2 or 4.1 "
                         "is expected)");
      }
    require(triangulation.n_active_cells() > 0,
            "Geometry: gmsh file '" + mesh_file + "' holds no cells");
    require(triangulation.all_reference_cells_are_hyper_cube(),
            "Geometry: gmsh file '" + mesh_file +
              "' holds triangles; quadrilaterals only are supported "
              "(recombine the mesh, e.g. 'Recombine Surface' in gmsh, as "
              "meshes/disk.geo does)");
  }

  void
  BodyGeometry::set_boundary_and_manifold_ids(
    Triangulation<2> &triangulation) const
  {
    // Built-in meshes and gmsh files alike: a boundary face is on the curved
    // edge if its vertices lie on the circle, else on the symmetry line.
    const double tolerance = 1e-8 * body_radius;
    triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
    unsigned int n_curved = 0, n_symmetry = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const bool on_circle =
              std::abs(face->vertex(0).distance(center()) - body_radius) <
                tolerance &&
              std::abs(face->vertex(1).distance(center()) - body_radius) <
                tolerance;
            const bool on_axis = std::abs(face->vertex(0)[1]) < tolerance &&
                                 std::abs(face->vertex(1)[1]) < tolerance;
            if (on_circle)
              {
                face->set_boundary_id(BoundaryIds::curved);
                face->set_manifold_id(curved_manifold_id);
                ++n_curved;
              }
            else if (on_axis && symmetry_boundary)
              {
                face->set_boundary_id(BoundaryIds::symmetry);
                ++n_symmetry;
              }
            else
              throw InputError(
                body_kind == Body::sphere ?
                  "Geometry: a boundary face of the mesh is neither on the "
                  "circle of radius 'Radius' centred at (R, 0) nor on the "
                  "axis y = 0: a sphere needs its meridian half disk y >= 0" :
                  "Geometry: a boundary face of the mesh is neither on the "
                  "circle of radius 'Radius' centred at (R, 0) nor on the "
                  "symmetry line of a half disk: check 'Radius', 'Domain' "
                  "and the mesh file");
          }
    require(n_curved > 0, "Geometry: the mesh has no curved boundary");
    require(!symmetry_boundary || n_symmetry > 0,
            body_kind == Body::sphere ?
              "Geometry: a sphere's mesh must be its meridian half disk "
              "y >= 0, with the axis y = 0 on its boundary" :
              "Geometry: 'Domain = half disk' but the mesh has no symmetry "
              "line on y = 0");
  }

  void
  BodyGeometry::refine_toward_contact_point(
    Triangulation<2> &triangulation) const
  {
    for (unsigned int step = 1; step <= n_contact_refinements; ++step)
      {
        const double distance = body_radius / std::pow(2., step);
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(contact_point()) < distance)
                {
                  cell->set_refine_flag();
                  break;
                }
        triangulation.execute_coarsening_and_refinement();
      }
  }
} // namespace DiskImpact
