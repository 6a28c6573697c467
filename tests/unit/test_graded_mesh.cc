// The mesh graded toward the contact point: its finest elements fill the
// zone of 'Fine zone radius' r (in contact half-widths a) and grow beyond.

#include "body/geometry.h"
#include "half_disk.h"
#include "impact/measured_contact_grading.h"

#include <deal.II/grid/tria.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;

namespace
{
  /// The half disk (one global refinement) graded toward the contact point
  /// for half-width @p a, 6 elements across it, grading 0.6, fine zone
  /// radius @p r.
  void
  graded_half_disk(dealii::Triangulation<2> &triangulation,
                   const double              a,
                   const double              r)
  {
    const BodyGeometry geometry = half_disk(1);
    geometry.create_triangulation(triangulation);
    refine_toward_contact(
      triangulation, geometry.contact_point(), a, 6, 0.6, r);
  }

  /// The contact point of the half disk.
  const dealii::Point<2> contact_point = half_disk(1).contact_point();

  /// The largest element size h (diameter / sqrt 2) among the cells whose
  /// centre lies within [@p from, @p to] of the contact point.
  double
  largest_size(const dealii::Triangulation<2> &triangulation,
               const double                    from,
               const double                    to)
  {
    double largest = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const double distance = cell->center().distance(contact_point);
        if (distance >= from && distance <= to)
          largest = std::max(largest, cell->diameter() / std::sqrt(2.));
      }
    return largest;
  }
} // namespace

TEST_CASE("the finest elements fill the fine zone and grow beyond it",
          "[geometry]")
{
  const double             a     = 0.2;
  const double             h_min = a / 6;
  dealii::Triangulation<2> wide, narrow;
  graded_half_disk(wide, a, 1.5);
  graded_half_disk(narrow, a, 0.5);

  // Within r a every element has the finest size; the quadtree halves
  // sizes, so the finest are between h_min / 2 and h_min.
  CHECK(largest_size(wide, 0., 1.5 * a) <= h_min);
  CHECK(largest_size(narrow, 0., 0.5 * a) <= h_min);
  // Around the contact zone's edge (0.9 a to 1.1 a) the narrow zone's
  // elements have grown beyond the finest size, the wide zone's not.
  CHECK(largest_size(wide, 0.9 * a, 1.1 * a) <= h_min);
  CHECK(largest_size(narrow, 0.9 * a, 1.1 * a) > h_min);
  // Every element meets the graded size h_min + 0.6 (d - r a), d the
  // distance of its nearest point (centre less its size) to the contact.
  for (const auto *triangulation : {&wide, &narrow})
    {
      const double r = triangulation == &wide ? 1.5 : 0.5;
      for (const auto &cell : triangulation->active_cell_iterators())
        {
          const double h = cell->diameter() / std::sqrt(2.);
          const double d =
            std::max(0., cell->center().distance(contact_point) - h);
          CHECK(h <= h_min + 0.6 * std::max(0., d - r * a) + 1e-12);
        }
    }
  // The narrow zone takes fewer cells.
  CHECK(narrow.n_active_cells() < 0.8 * wide.n_active_cells());
}

TEST_CASE("a mesh graded for a measured contact keeps the element size",
          "[graded_mesh]")
{
  // 6 elements across Hertz's half-width: 6 * 1.576 = 9.46 across a plastic
  // contact 1.576 times wider, rounded to the nearest even count.
  CHECK(elements_across_measured_contact(6, 0.032, 0.032 * 1.576) == 10);
  CHECK(elements_across_measured_contact(6, 0.032, 0.032) == 6);
  CHECK(elements_across_measured_contact(12, 0.05, 0.075) == 18);
  CHECK(elements_across_measured_contact(8, 0.05, 0.0374) == 6);
  // never fewer than 4
  CHECK(elements_across_measured_contact(2, 0.05, 0.01) == 4);
}
