#include "body/partner.h"

#include "base/input_error.h"
#include "body/geometry.h"

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  void
  Partner::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Partner");
    {
      prm.declare_entry("Kind",
                        "wall",
                        Patterns::Selection("wall|body"),
                        "What the body collides with: 'wall' (the rigid wall "
                        "of subsection Contact) or 'body' (a second "
                        "deformable body of the same kind, plane model and "
                        "domain, with the radius and material below, on the "
                        "other side of the plane x = 0; the impact tasks "
                        "only).");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(),
                        "Kind = body: its radius R2 [length]. Its centre is "
                        "at (-Gap - R2, Offset).");
      prm.declare_entry("Gap",
                        "0",
                        Patterns::Double(),
                        "Kind = body: the distance between the two "
                        "undeformed surfaces along the impact axis [length], "
                        "0 <= Gap <= 0.05 R (negative: the bodies overlap).");
      prm.declare_entry("Offset",
                        "0",
                        Patterns::Double(),
                        "Kind = body: the partner's centre off the impact "
                        "axis [length]; only head-on collisions (0) are "
                        "computed.");
      Material::declare_parameters(prm);
    }
    prm.leave_subsection();
  }

  void
  Partner::parse_parameters(ParameterHandler   &prm,
                            const BodyGeometry &geometry,
                            const Material     &body_material)
  {
    prm.enter_subsection("Partner");
    kind                = prm.get("Kind") == "body" ? Kind::body : Kind::wall;
    partner_radius      = prm.get_double("Radius");
    partner_gap         = prm.get_double("Gap");
    const double offset = prm.get_double("Offset");
    try
      {
        partner_material.parse_parameters(prm);
      }
    catch (const InputError &e)
      {
        prm.leave_subsection();
        throw InputError(std::string("Partner: ") + e.what());
      }
    prm.leave_subsection();
    if (kind == Kind::wall)
      return;

    const double R = geometry.radius();
    require(partner_radius > 0.,
            "Partner: 'Radius' must be positive, got " +
              Utilities::to_string(partner_radius));
    require(partner_gap >= 0.,
            "Partner: 'Gap = " + Utilities::to_string(partner_gap) +
              "': the bodies overlap at the start (the gap between their "
              "surfaces must be >= 0)");
    require(partner_gap <= 0.05 * R,
            "Partner: 'Gap = " + Utilities::to_string(partner_gap) +
              "' is more than 0.05 R: start the bodies closer");
    require(std::abs(offset) < R + partner_radius,
            "Partner: 'Offset = " + Utilities::to_string(offset) +
              "': the partner misses the body (|Offset| >= R + R2)");
    require(offset == 0.,
            "Partner: 'Offset = " + Utilities::to_string(offset) +
              "': only head-on collisions are computed (Offset = 0)");
    const bool model_given = partner_material.plane_model_given();
    if (geometry.is_axisymmetric())
      {
        require(!model_given,
                "Partner: 'Plane model' is a disk entry; a sphere's partner "
                "is a sphere (remove 'Plane model')");
        try
          {
            partner_material.make_axisymmetric();
          }
        catch (const InputError &e)
          {
            throw InputError(std::string("Partner: ") + e.what());
          }
      }
    else
      {
        require(!model_given ||
                  partner_material.plane_model() == body_material.plane_model(),
                "Partner: 'Plane model = " +
                  partner_material.plane_model_name() +
                  "' differs from the body's '" +
                  body_material.plane_model_name() +
                  "' (both disks are plane strain or both plane stress)");
        partner_material.set(body_material.plane_model(),
                             partner_material.young_modulus(),
                             partner_material.poisson_ratio(),
                             partner_material.density(),
                             partner_material.relaxation_time());
      }
  }

  bool
  Partner::is_body() const
  {
    return kind == Kind::body;
  }

  double
  Partner::radius() const
  {
    return partner_radius;
  }

  Partner
  Partner::with_radius(const double radius) const
  {
    require(radius > 0.,
            "Partner: the radius must be positive, got " +
              Utilities::to_string(radius));
    Partner partner        = *this;
    partner.partner_radius = radius;
    return partner;
  }

  const Material &
  Partner::material() const
  {
    return partner_material;
  }

  Point<2>
  Partner::center() const
  {
    return Point<2>(-partner_gap - partner_radius, 0.);
  }

  double
  Partner::gap() const
  {
    return partner_gap;
  }

  void
  Partner::create_pair_triangulation(const BodyGeometry &geometry,
                                     Triangulation<2>   &triangulation,
                                     const double        max_cells) const
  {
    // Each body's built-in coarse mesh, the
    // partner's scaled to R2 and mirrored in x = 0 behind the gap.
    Triangulation<2> body, partner;
    geometry.create_coarse_triangulation(body);
    geometry.with_radius(partner_radius).create_coarse_triangulation(partner);
    auto [vertices, cells, subcells] =
      GridTools::get_coarse_mesh_description(body);
    auto [vertices2, cells2, unused] =
      GridTools::get_coarse_mesh_description(partner);
    (void)subcells;
    (void)unused;
    for (auto &x : vertices2)
      x = Point<2>(-x[0] - partner_gap, x[1]);
    // The mirror image has clockwise cells: turn them round.
    GridTools::invert_all_negative_measure_cells(vertices2, cells2);
    const unsigned int offset = vertices.size();
    for (auto &cell : cells)
      cell.material_id = 0;
    for (auto &cell : cells2)
      {
        for (auto &v : cell.vertices)
          v += offset;
        cell.material_id = 1;
        cells.push_back(cell);
      }
    vertices.insert(vertices.end(), vertices2.begin(), vertices2.end());
    triangulation.create_triangulation(vertices, cells, SubCellData());

    // Boundary and manifold ids: a face on a body's circle is its curved
    // edge, any other boundary face lies on the symmetry line y = 0.
    const double tolerance = 1e-8 * std::min(geometry.radius(), partner_radius);
    const auto   on_circle = [&](const auto     &face,
                               const Point<2> &center,
                               const double    radius) {
      return std::abs(face->vertex(0).distance(center) - radius) < tolerance &&
             std::abs(face->vertex(1).distance(center) - radius) < tolerance;
    };
    triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const bool is_partner = cell->material_id() == 1;
            if (on_circle(face,
                          is_partner ? center() : geometry.center(),
                          is_partner ? partner_radius : geometry.radius()))
              {
                face->set_boundary_id(is_partner ? BoundaryIds::partner_curved :
                                                   BoundaryIds::curved);
                face->set_manifold_id(is_partner ? partner_manifold_id :
                                                   curved_manifold_id);
              }
            else
              face->set_boundary_id(BoundaryIds::symmetry);
          }
    triangulation.set_manifold(curved_manifold_id,
                               SphericalManifold<2>(geometry.center()));
    triangulation.set_manifold(partner_manifold_id,
                               SphericalManifold<2>(center()));
    geometry.refine(triangulation, max_cells);
  }
} // namespace DiskImpact
