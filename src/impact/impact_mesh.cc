#include "impact/impact_mesh.h"

#include "base/input_error.h"
#include "body/conforming_mesh.h"
#include "body/solid_geometry.h"
#include "impact/impact_estimates.h"
#include "reference/wall_contact_theory.h"
#include "run/parameters.h"

#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  double
  graded_width(const Parameters &parameters)
  {
    if (parameters.impact.graded_half_width() > 0.)
      return parameters.impact.graded_half_width() *
             parameters.geometry.radius();
    return largest_half_width(parameters);
  }

  double
  largest_half_width(const Parameters &parameters)
  {
    return Reference::wall_contact_theory(parameters.geometry.is_sphere())
             ->half_width(estimate_collision(parameters).largest_load) *
           parameters.geometry.radius();
  }

  double
  fine_zone_factor(const Parameters &parameters)
  {
    return parameters.impact.fine_zone_radius() +
           contact_drift(parameters) / graded_width(parameters);
  }

  namespace
  {
    /// The contact line's direction: a disk's rim in 3D touches the wall
    /// along z; zero (a contact point) otherwise.
    template <int dim>
    Tensor<1, dim>
    rim_direction(const BodyGeometry &geometry)
    {
      Tensor<1, dim> direction;
      if (dim == 3 && geometry.body() == Body::disk)
        direction[dim - 1] = 1.;
      return direction;
    }

    /// 'Graded mesh = hanging nodes': the geometry's mesh (with a partner
    /// body both bodies') refined toward the contact.
    template <int dim>
    void
    create_graded_mesh(const Parameters   &parameters,
                       Triangulation<dim> &triangulation,
                       const double        max_cells)
    {
      const auto &geometry = parameters.geometry;
      if constexpr (dim == 3)
        create_solid_triangulation(geometry, triangulation, max_cells);
      else if (parameters.partner.is_body())
        parameters.partner.create_pair_triangulation(geometry,
                                                     triangulation,
                                                     max_cells);
      else
        geometry.create_triangulation(triangulation, max_cells);
      refine_toward_contact(triangulation,
                            embedded<dim>(geometry.contact_point()),
                            graded_width(parameters),
                            parameters.impact.elements_across_contact(),
                            parameters.impact.grading(),
                            fine_zone_factor(parameters),
                            max_cells,
                            rim_direction<dim>(geometry));
    }

    /// The largest cell size of a 2D mesh (diameter over sqrt(2)).
    double
    largest_cell_size(const Triangulation<2> &mesh)
    {
      double size = 0.;
      for (const auto &cell : mesh.active_cell_iterators())
        size = std::max(size, cell->diameter() / std::sqrt(2.));
      return size;
    }

    /// The planes z of a disk's layers, graded toward its faces like the
    /// section toward the contact (with 'Layer refinement' k, like a
    /// section refined k more times: every size over 2^k): from the
    /// mid-plane to the face for the quarter, mirrored for the whole disk.
    std::vector<double>
    layer_planes(const Parameters &parameters, const double largest)
    {
      const auto  &impact = parameters.impact;
      const double a      = graded_width(parameters);
      const double scale  = std::pow(0.5, impact.layer_refinement());
      const std::vector<double> half =
        layers_graded_toward_face(0.5 * parameters.geometry.thickness(),
                                  scale * a / impact.elements_across_contact(),
                                  scale * impact.grading(),
                                  impact.fine_zone_radius() * a,
                                  scale * largest);
      std::vector<double> z;
      if (!parameters.geometry.has_symmetry_boundary())
        for (auto it = half.rbegin(); it + 1 != half.rend(); ++it)
          z.push_back(-*it);
      z.insert(z.end(), half.begin(), half.end());
      return z;
    }

    /**
     * 'Graded mesh = conforming': the geometry's mesh graded with half the
     * elements across and twice the grading, halved without hanging
     * nodes; a disk in 3D extrudes it through layer_planes().
     */
    template <int dim>
    void
    create_conforming_mesh(const Parameters   &parameters,
                           Triangulation<dim> &triangulation,
                           const double        max_cells)
    {
      Parameters coarser = parameters;
      coarser.impact     = parameters.impact.with_mesh_coarsened();
      Triangulation<2> graded(
        Triangulation<2>::limit_level_difference_at_vertices);
      create_graded_mesh(coarser, graded, max_cells);
      if constexpr (dim == 2)
        split_into_conforming_mesh(graded, triangulation);
      else
        {
          Triangulation<2> section;
          split_into_conforming_mesh(graded, section);
          const std::vector<double> z =
            layer_planes(parameters, largest_cell_size(section));
          const double n_cells =
            double(section.n_active_cells()) * double(z.size() - 1);
          require(n_cells <= max_cells,
                  "Graded mesh: the conforming mesh (" +
                    std::to_string(section.n_active_cells()) +
                    " cells in the section, " + std::to_string(z.size() - 1) +
                    " layers) would have " + approximately(n_cells) +
                    " cells, more than this machine's memory holds");
          extrude_disk(parameters.geometry, section, z, triangulation);
        }
    }

    /// Throws an InputError if a 3D mesh of Q_@p degree elements has more
    /// DoFs than @p max_cells cells of a large mesh would (3 k^3 each):
    /// thin bodies have more DoFs per cell.
    void
    check_dofs(const Triangulation<3> &mesh,
               const unsigned int      degree,
               const double            max_cells)
    {
      const double k     = degree;
      const double n_dofs = 3. * (mesh.n_used_vertices() +
                                  (k - 1.) * mesh.n_active_lines() +
                                  (k - 1.) * (k - 1.) * mesh.n_active_quads() +
                                  std::pow(k - 1., 3) * mesh.n_active_cells());
      const double budget = max_cells * 3. * k * k * k;
      require(n_dofs <= budget,
              "Graded mesh: the mesh (" +
                std::to_string(mesh.n_active_cells()) + " cells of degree " +
                std::to_string(degree) + ") has about " +
                approximately(n_dofs) + " DoFs, more than the " +
                approximately(budget) + " this machine's memory holds");
    }
  } // namespace

  template <int dim>
  void
  create_impact_mesh(const Parameters   &parameters,
                     Triangulation<dim> &triangulation,
                     const double        max_cells)
  {
    if (parameters.impact.conforming_mesh())
      create_conforming_mesh(parameters, triangulation, max_cells);
    else
      create_graded_mesh(parameters, triangulation, max_cells);
    if constexpr (dim == 3)
      if (std::isfinite(max_cells))
        check_dofs(triangulation,
                   parameters.finite_element.degree,
                   max_cells);
  }

  template void
  create_impact_mesh(const Parameters &, Triangulation<2> &, double);
  template void
  create_impact_mesh(const Parameters &, Triangulation<3> &, double);
} // namespace DiskImpact
