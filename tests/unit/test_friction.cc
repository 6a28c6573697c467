// Coulomb friction at the wall's contact points (ContactZone::
// enable_friction()) and the body's rotation taken exactly
// (enable_rotation()): the step force's Jacobian against its finite
// differences, sticking and slipping, with and without the rotation as an
// unknown; the mean traction of a sliding step; and the energy friction
// dissipates.

#include "body/geometry.h"
#include "contact/contact.h"
#include "contact/contact_operator.h"
#include "contact/contact_zone.h"
#include "elasticity/elasticity_operator.h"
#include "half_disk.h"
#include "material/material.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <string>

using namespace DiskImpact;

namespace
{
  /// The whole disk of radius 1 (Q2, plane stress, nu = 0.3, E = rho = 1)
  /// touching the wall x = 0 at the origin, with the penalty law and a
  /// contact zone with friction mu = 0.3, all its DoFs active.
  struct FrictionalDisk
  {
    explicit FrictionalDisk(const bool with_rotation)
        : triangulation(MPI_COMM_WORLD)
        , op(2)
    {
      const BodyGeometry geometry = disk_geometry("full disk", 3);
      geometry.create_triangulation(triangulation);
      op.setup(triangulation, geometry);
      Material material;
      material.set(PlaneModel::plane_stress, 1., 0.3, 1., 0.);
      op.assemble(material);
      dealii::ParameterHandler prm;
      ContactParameters::declare_parameters(prm);
      ContactParameters contact;
      contact.parse_parameters(prm);
      const auto law = contact.law(
        {material.in_plane_young_modulus(), smallest_edge_face(op), 1.});
      zone =
        std::make_unique<ContactZone>(op, contact.wall(), law, center, 0.1);
      zone->enable_friction(mu);
      if (with_rotation)
        zone->enable_rotation();
      std::vector<unsigned int> all(zone->candidate_dofs().size());
      std::iota(all.begin(), all.end(), 0u);
      zone->activate(all);
    }

    /// The values on C of the field @p expression ("u_x; u_y" in x, y),
    /// with the angle @p theta appended if the rotation is tracked.
    dealii::Vector<double>
    on_contact(const std::string &expression, const double theta) const
    {
      auto                      field = op.create_vector();
      dealii::FunctionParser<2> function(2);
      function.initialize("x,y", expression, {});
      dealii::VectorTools::interpolate(op.get_mapping(),
                                       op.get_dof_handler(),
                                       function,
                                       field);
      const auto            &dofs = zone->candidate_dofs();
      dealii::Vector<double> on_D(dofs.size());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        on_D[i] = field[dofs[i]];
      dealii::Vector<double> values = zone->restrict_to_active(on_D);
      if (!zone->tracks_rotation())
        return values;
      dealii::Vector<double> with_angle(values.size() + 1);
      for (unsigned int i = 0; i < values.size(); ++i)
        with_angle[i] = values[i];
      with_angle[values.size()] = theta;
      return with_angle;
    }

    /// The largest difference between the step force's Jacobian at @p u1
    /// and its central differences, relative to the Jacobian's largest
    /// entry.
    double
    jacobian_error(const dealii::Vector<double> &u0,
                   const dealii::Vector<double> &u1) const
    {
      const auto force = [&](const dealii::Vector<double> &u, bool jacobian) {
        return zone->step_force(
          u0, u, ContactAverage::discrete_gradient, 0.5, jacobian);
      };
      const auto   exact = force(u1, true).jacobian;
      const double h     = 1e-10;
      double       error = 0.;
      for (unsigned int j = 0; j < u1.size(); ++j)
        {
          dealii::Vector<double> plus(u1), minus(u1);
          plus[j] += h;
          minus[j] -= h;
          const auto fp = force(plus, false).force;
          const auto fm = force(minus, false).force;
          for (unsigned int i = 0; i < u1.size(); ++i)
            error = std::max(error,
                             std::abs((fp[i] - fm[i]) / (2. * h) -
                                      exact(i, j)));
        }
      return error / exact.linfty_norm();
    }

    static constexpr double                         mu = 0.3;
    const dealii::Point<2>                          center{1., 0.};
    dealii::parallel::distributed::Triangulation<2> triangulation;
    ElasticityOperator<2>                           op;
    std::unique_ptr<ContactZone>                    zone;
  };

  /// The start and end of a step pressing the disk 2e-3 and 3e-3 into
  /// the wall, turned by 2e-3 and 5e-3, and moving it along the wall by
  /// @p shift: points near the contact stick for a small shift and slip
  /// for a large one.
  std::pair<dealii::Vector<double>, dealii::Vector<double>>
  step(const FrictionalDisk &disk, const double shift)
  {
    return {disk.on_contact("-0.002; 0", 0.002),
            disk.on_contact("-0.003; " + std::to_string(shift), 0.005)};
  }
} // namespace

TEST_CASE("the friction force's Jacobian is its derivative",
          "[friction][contact][fe]")
{
  for (const bool with_rotation : {false, true})
    for (const double shift : {1e-7, 1e-4})
      {
        INFO("rotation " << with_rotation << ", shift " << shift);
        FrictionalDisk disk(with_rotation);
        const auto [u0, u1] = step(disk, shift);
        const auto state =
          disk.zone
            ->step_force(u0, u1, ContactAverage::discrete_gradient, 0.5, false)
            .state;
        REQUIRE(state.force_average > 0.);
        CHECK(disk.jacobian_error(u0, u1) < 1e-5);
      }
}

TEST_CASE("a sliding step's traction is mu times its pressure and "
          "dissipates",
          "[friction][contact][fe]")
{
  // Moved 1e-2 along the wall (the sticking points' trial traction k 1e-2 /
  // 2 is far beyond mu p): every point slides, so the step's tangential
  // force is -mu times its normal force, and the friction work, -tau_bar
  // ds with no elastic stick energy left, is positive. A tiny shift sticks:
  // no work is dissipated and the force is below the bound.
  FrictionalDisk disk(false);
  auto [u0, u1] = step(disk, 1e-2);
  auto state =
    disk.zone->step_force(u0, u1, ContactAverage::discrete_gradient, 0.5, false)
      .state;
  CHECK(state.tangential_force_average[0] ==
        Approx(-FrictionalDisk::mu * state.force_average).epsilon(1e-12));
  CHECK(state.friction_work > 0.);
  std::tie(u0, u1) = step(disk, 1e-9);
  state =
    disk.zone->step_force(u0, u1, ContactAverage::discrete_gradient, 0.5, false)
      .state;
  CHECK(std::abs(state.tangential_force_average[0]) <
        FrictionalDisk::mu * state.force_average);
  CHECK(std::abs(state.friction_work) <= 1e-12 * state.energy);
}
