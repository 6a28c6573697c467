// Mode labelling: the counting rules on synthetic harmonic content, and the
// boundary harmonic analysis on interpolated analytic fields.

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "modal/mode_labelling.h"

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;
using Reference::ModeFamily;
using Reference::ModeLabel;

namespace
{
  /// Harmonic content with all power in order n, radial or tangential.
  HarmonicContent
  pure(const unsigned int n, const bool radial, const unsigned int n_max = 6)
  {
    HarmonicContent h;
    h.radial_power.assign(n_max + 1, 1e-6);
    h.tangential_power.assign(n_max + 1, 1e-6);
    (radial ? h.radial_power : h.tangential_power)[n] = 1.;
    return h;
  }

  /// u = (a(r) cos(n phi)) e_r about centre c: a radial harmonic of order n.
  class RadialHarmonic : public dealii::Function<2>
  {
  public:
    RadialHarmonic(const unsigned int n, const dealii::Point<2> &c)
        : dealii::Function<2>(2)
        , n(n)
        , c(c)
    {
    }
    double
    value(const dealii::Point<2> &p,
          const unsigned int      component) const override
    {
      const auto   x   = p - c;
      const double phi = std::atan2(x[1], x[0]);
      const double u_r = x.norm() * std::cos(n * phi);
      return u_r * (component == 0 ? std::cos(phi) : std::sin(phi));
    }

  private:
    unsigned int     n;
    dealii::Point<2> c;
  };
} // namespace

TEST_CASE("labels: pairs on the full disk, singles on the half disk",
          "[labelling]")
{
  const std::vector<double> eigenvalues{0., 0., 0., 2., 2., 3., 4., 4., 5.};
  const std::vector<HarmonicContent> harmonics{pure(1, true),
                                               pure(1, true),
                                               pure(0, false),
                                               pure(2, true),
                                               pure(2, false),
                                               pure(0, true),
                                               pure(2, true),
                                               pure(2, true),
                                               pure(0, false)};
  const auto full = label_modes(eigenvalues, harmonics, 1e-6, false);
  CHECK(full[0].label.family == ModeFamily::rigid);
  CHECK(full[2].label.family == ModeFamily::rigid);
  CHECK(full[3].label == ModeLabel{2, 0, ModeFamily::mixed});
  CHECK(full[4].label == ModeLabel{2, 0, ModeFamily::mixed});
  CHECK(full[5].label == ModeLabel{0, 0, ModeFamily::radial});
  CHECK(full[6].label == ModeLabel{2, 1, ModeFamily::mixed});
  CHECK(full[7].label == ModeLabel{2, 1, ModeFamily::mixed});
  CHECK(full[8].label == ModeLabel{0, 0, ModeFamily::torsional});

  const auto half = label_modes(eigenvalues, harmonics, 1e-6, true);
  CHECK(half[3].label == ModeLabel{2, 0, ModeFamily::mixed});
  CHECK(half[4].label == ModeLabel{2, 1, ModeFamily::mixed});
  CHECK(half[6].label == ModeLabel{2, 2, ModeFamily::mixed});
}

TEST_CASE("boundary harmonics of interpolated fields", "[labelling][fe]")
{
  for (const bool half : {false, true})
    {
      dealii::ParameterHandler prm;
      BodyGeometry::declare_parameters(prm);
      prm.enter_subsection("Geometry");
      prm.set("Domain", half ? "half disk" : "full disk");
      prm.set("Global refinements", "2");
      prm.leave_subsection();
      BodyGeometry geometry;
      geometry.parse_parameters(prm);

      dealii::parallel::distributed::Triangulation<2> triangulation(
        MPI_COMM_WORLD);
      geometry.create_triangulation(triangulation);
      ElasticityOperator<2> op(2);
      op.setup(triangulation, geometry);

      for (const unsigned int n : {0u, 1u, 3u, 5u})
        {
          CAPTURE(half, n);
          auto u = op.create_vector();
          dealii::VectorTools::interpolate(op.get_mapping(),
                                           op.get_dof_handler(),
                                           RadialHarmonic(n, geometry.center()),
                                           u);
          const auto h =
            compute_boundary_harmonics(op, geometry, op.create_ghosted(u), 8);
          CHECK(h.dominant_order() == n);
          CHECK(h.dominant_fraction() > 0.999);
          CHECK(h.radial_power[n] > 1e3 * h.tangential_power[n]);
        }
    }
}
