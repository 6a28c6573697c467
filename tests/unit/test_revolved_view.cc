// The 3D view of a sphere: a meridian patch revolved about the axis y = 0.
// One Q1 patch with a curved edge on the circle |x - c| = R and an edge on
// the axis: the planes at both ends of the sweep, strips of the curved edge
// only, points on the surface of revolution, vectors turned with the
// meridian and the stress tensor's invariants kept (hoop stress included).

#include "output/revolved_view.h"

#include <deal.II/base/symmetric_tensor.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;
using dealii::Point;
using dealii::DataComponentInterpretation::component_is_part_of_tensor;
using dealii::DataComponentInterpretation::component_is_part_of_vector;
using dealii::DataComponentInterpretation::DataComponentInterpretation;
using dealii::DataOutBase::Patch;

namespace
{
  /// A Q1 patch of the meridian of the unit sphere about the origin: the
  /// edge y = 0 on the axis, the edge from (1, 0) to (sqrt(1/2), sqrt(1/2))
  /// on the surface; coordinates in the last two rows.
  Patch<2, 2>
  meridian_patch()
  {
    Patch<2, 2> patch;
    patch.n_subdivisions       = 1;
    patch.points_are_available = true;
    // rows: u_x, u_r, stress (xx, xr, rx, rr), hoop_stress, then x, y
    patch.data.reinit(9, 4);
    const Point<2> points[4] = {Point<2>(0.5, 0.),
                                Point<2>(1., 0.),
                                Point<2>(0.5, 0.5),
                                Point<2>(std::sqrt(0.5), std::sqrt(0.5))};
    for (unsigned int j = 0; j < 4; ++j)
      {
        patch.data(0, j)  = 0.1 * (j + 1);  // u_x
        patch.data(1, j)  = -0.2 * (j + 1); // u_r
        patch.data(2, j)  = 1. + j;         // sigma_xx
        patch.data(3, j)  = 0.5;            // sigma_xr
        patch.data(4, j)  = 0.5;
        patch.data(5, j)  = -2.;    // sigma_rr
        patch.data(6, j)  = 3. - j; // sigma_theta
        patch.data(7, j)  = points[j][0];
        patch.data(8, j)  = points[j][1];
        patch.vertices[j] = points[j];
      }
    return patch;
  }
} // namespace

TEST_CASE("revolved view: planes, curved strips, rotated fields",
          "[output][axisymmetric]")
{
  const std::vector<std::string> names = {
    "u", "u", "stress", "stress", "stress", "stress", "hoop_stress"};
  const std::vector<std::tuple<unsigned int,
                               unsigned int,
                               std::string,
                               DataComponentInterpretation>>
                     ranges  = {{0, 1, "u", component_is_part_of_vector},
                                {2, 5, "stress", component_is_part_of_tensor}};
  const double       angle   = 1.5 * M_PI;
  const unsigned int sectors = 6;
  const Patch<2, 2>  source  = meridian_patch();
  const RevolvedView view({source},
                          names,
                          ranges,
                          "hoop_stress",
                          Point<2>(0., 0.),
                          1.,
                          angle,
                          sectors);

  // Two planes and one strip per sector of the curved edge (points 1, 3):
  // the straight edges (axis y = 0, and x = 0.5) are no surface.
  REQUIRE(view.get_patches().size() == 2 + sectors);
  REQUIRE(view.get_dataset_names().size() == 3 + 9 + 1);
  REQUIRE(view.get_nonscalar_data_ranges().size() == 2);
  // quadrilaterals (the VTU writer's cell type comes from it)
  for (const auto &patch : view.get_patches())
    CHECK(patch.reference_cell == dealii::ReferenceCells::Quadrilateral);

  for (const auto &patch : view.get_patches())
    for (unsigned int j = 0; j < 4; ++j)
      {
        const Point<3> x(patch.data(13, j),
                         patch.data(14, j),
                         patch.data(15, j));
        const double   r   = std::hypot(x[1], x[2]);
        const double   phi = std::atan2(x[2], x[1]);
        // The meridian point this one came from: same x and r.
        unsigned int k = 4;
        for (unsigned int i = 0; i < 4; ++i)
          if (std::abs(source.data(7, i) - x[0]) < 1e-6 &&
              std::abs(source.data(8, i) - r) < 1e-6)
            k = i;
        REQUIRE(k < 4);
        CAPTURE(j, k, phi);
        const double c = std::cos(phi), s = std::sin(phi);
        // vector (u_x, u_r c, u_r s), when off the axis
        CHECK(patch.data(0, j) == Approx(source.data(0, k)));
        if (r > 1e-6)
          {
            CHECK(patch.data(1, j) ==
                  Approx(source.data(1, k) * c).margin(1e-6));
            CHECK(patch.data(2, j) ==
                  Approx(source.data(1, k) * s).margin(1e-6));
          }
        // the tensor's trace and determinant are those of
        // diag-block(meridian stress, hoop stress)
        dealii::SymmetricTensor<2, 3> t;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = a; b < 3; ++b)
            t[a][b] = patch.data(3 + 3 * a + b, j);
        CHECK(patch.data(3 + 1, j) == Approx(patch.data(3 + 3, j)));
        const double xx = source.data(2, k), xr = source.data(3, k),
                     rr = source.data(5, k), tt = source.data(6, k);
        CHECK(dealii::trace(t) ==
              Approx(xx + rr + tt).epsilon(1e-6).margin(1e-6));
        CHECK(dealii::determinant(t) ==
              Approx((xx * rr - xr * xr) * tt).epsilon(1e-5).margin(1e-5));
        CHECK(patch.data(12, j) == Approx(tt).margin(1e-6));
      }
  // the strips lie on the unit sphere, the planes at phi = 0 and 3 pi / 2
  for (unsigned int p = 2; p < view.get_patches().size(); ++p)
    for (unsigned int j = 0; j < 4; ++j)
      {
        const auto &patch = view.get_patches()[p];
        CHECK(std::hypot(patch.data(13, j),
                         std::hypot(patch.data(14, j), patch.data(15, j))) ==
              Approx(1.).epsilon(1e-6));
      }
  for (unsigned int j = 0; j < 4; ++j)
    {
      CHECK(view.get_patches()[0].data(15, j) == Approx(0.).margin(1e-7));
      CHECK(view.get_patches()[1].data(14, j) == Approx(0.).margin(1e-7));
    }
}
