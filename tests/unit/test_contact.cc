// Contact: the penalty and exponential wall laws, the contact operator's
// tangent against finite differences of its residual, and the log contact law
// with its Lambert-W inverse.

#include "base/input_error.h"
#include "body/geometry.h"
#include "contact/contact.h"
#include "contact/contact_operator.h"
#include "contact/exponential_law.h"
#include "contact/penalty_law.h"
#include "elasticity/elasticity_operator.h"
#include "half_disk.h"
#include "reference/log_contact_law.h"

#include <deal.II/base/function_parser.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace DiskImpact;

namespace
{
  /// The penalty law of stiffness @p stiffness (kappa = 100, h = 1).
  std::shared_ptr<const ContactLaw>
  penalty(const double stiffness)
  {
    auto law = std::make_shared<PenaltyLaw>();
    law->set_scales({stiffness / law->penalty_factor(), 1., 1.});
    return law;
  }

  /// The exponential law of alpha = 200 on R = 1 with a threshold large
  /// enough to see (1e-3 instead of 1e-16).
  std::shared_ptr<const ContactLaw>
  exponential()
  {
    auto law = std::make_shared<ExponentialLaw>();
    law->set(200., 1e-3);
    return law;
  }

  /// p = -dE/dg and dp/dg by central differences at the gap @p g (away
  /// from the kink at 0).
  void
  check_pressure_is_energy_gradient(const ContactLaw &law, const double g)
  {
    const double h = 1e-9;
    CHECK(law.pressure(g) ==
          Approx(-(law.energy(g + h) - law.energy(g - h)) / (2 * h))
            .epsilon(1e-6)
            .margin(1e-12));
    CHECK(law.pressure_derivative(g) ==
          Approx((law.pressure(g + h) - law.pressure(g - h)) / (2 * h))
            .epsilon(1e-6)
            .margin(1e-12));
  }
} // namespace

TEST_CASE("contact laws are selected by name from the registry", "[contact]")
{
  std::vector<std::string> names;
  for (const auto &entry : ContactLaws::all())
    names.push_back(entry.name);
  CHECK(names == std::vector<std::string>{"exponential", "penalty"});
  CHECK(dynamic_cast<PenaltyLaw *>(ContactLaws::create("penalty").get()));
  CHECK(
    dynamic_cast<ExponentialLaw *>(ContactLaws::create("exponential").get()));
  CHECK_THROWS_AS(ContactLaws::create("constraint"), InputError);

  // The law chosen in subsection Contact, scaled: k = kappa E2 / h.
  dealii::ParameterHandler prm;
  ContactParameters::declare_parameters(prm);
  prm.enter_subsection("Contact");
  prm.set("Law", "penalty");
  prm.set("Penalty factor", "50");
  prm.leave_subsection();
  ContactParameters contact;
  contact.parse_parameters(prm);
  const auto law = contact.law({2., 0.25, 1.});
  CHECK(law->pressure(-0.01) == Approx(50. * 2. / 0.25 * 0.01));
  CHECK(law->approximates_hard_contact());
  // A copy's law is its own: stiffening it leaves the original's.
  ContactParameters stiffer = contact;
  stiffer.stiffen_law(4.);
  CHECK(stiffer.law({2., 0.25, 1.})->pressure(-0.01) ==
        Approx(4. * law->pressure(-0.01)));
  CHECK(contact.law({2., 0.25, 1.})->pressure(-0.01) ==
        Approx(law->pressure(-0.01)));
}

TEST_CASE("penalty law: pressure, derivative and energy", "[contact]")
{
  const auto        held = penalty(250.);
  const ContactLaw &law  = *held;
  for (const double g : {-1e-3, -2e-5, 3e-5, 1e-2})
    {
      CAPTURE(g);
      CHECK(law.pressure(g) == Approx(g < 0 ? -250. * g : 0.));
      check_pressure_is_energy_gradient(law, g);
    }
}

TEST_CASE("penalty law: discrete gradient releases the exact energy",
          "[contact]")
{
  const auto        held       = penalty(300.);
  const ContactLaw &law        = *held;
  const double      pairs[][2] = {{1e-3, -2e-3},
                                  {-2e-3, 1e-3},
                                  {-1e-3, -3e-3},
                                  {2e-3, 5e-3},
                                  {-1e-3, -1e-3},
                                  {-1e-3, -1e-3 + 1e-16}};
  for (const auto &[g0, g1] : pairs)
    {
      CAPTURE(g0, g1);
      const double p = law.discrete_gradient_pressure(g0, g1);
      CHECK(p >= 0.);
      if (g0 != g1)
        CHECK(p * (g1 - g0) ==
              Approx(-(law.energy(g1) - law.energy(g0))).margin(1e-16));
      else
        CHECK(p == Approx(law.pressure(g0)));
      const double h = 1e-9;
      if (std::abs(g1 - g0) > 1e-6 && g1 != 0.)
        CHECK(law.discrete_gradient_derivative(g0, g1) ==
              Approx((law.discrete_gradient_pressure(g0, g1 + h) -
                      law.discrete_gradient_pressure(g0, g1 - h)) /
                     (2 * h))
                .epsilon(1e-5)
                .margin(1e-9));
    }
}

TEST_CASE("exponential law: pressure, energy and the discrete gradient",
          "[contact]")
{
  const auto        held = exponential();
  const ContactLaw &law  = *held;
  for (const double g : {-0.05, -1e-3, -2e-5, 3e-5})
    {
      CAPTURE(g);
      CHECK(law.pressure(g) == Approx(g < 0 ? 1e-3 * std::exp(-200. * g) : 0.));
      check_pressure_is_energy_gradient(law, g);
    }
  // The averaged pressure releases exactly the energy difference, also for
  // steps far below and far above the decay length 1 / 200, and its
  // derivative is that of the quotient.
  const double pairs[][2] = {{-0.01, -0.03},
                             {-0.03, -0.01},
                             {-0.02, -0.02 + 1e-9},
                             {-0.02, -0.02 - 1e-13},
                             {1e-3, -2e-3},
                             {-1e-3, 2e-3}};
  for (const auto &[g0, g1] : pairs)
    {
      CAPTURE(g0, g1);
      const double p = law.discrete_gradient_pressure(g0, g1);
      CHECK(p * (g1 - g0) == Approx(-(law.energy(g1) - law.energy(g0)))
                               .epsilon(1e-9)
                               .margin(1e-15 * std::abs(law.energy(g0))));
      const double step = 1e-6 * std::abs(g1 - g0) + 1e-12;
      CHECK(law.discrete_gradient_derivative(g0, g1) ==
            Approx((law.discrete_gradient_pressure(g0, g1 + step) -
                    law.discrete_gradient_pressure(g0, g1 - step)) /
                   (2 * step))
              .epsilon(1e-4));
    }
}

TEST_CASE("contact tangent is the derivative of the contact residual",
          "[contact][fe]")
{
  const BodyGeometry geometry = half_disk(3);

  dealii::parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
  geometry.create_triangulation(triangulation);
  ElasticityOperator<2> op(2);
  op.setup(triangulation, geometry, true);

  const RigidWall<2> wall{dealii::Point<2>(0., 0.),
                       dealii::Tensor<1, 2>({1., 0.})};
  // Both laws; the exponential one smooth, the penalty piecewise linear.
  const auto            law = GENERATE(penalty(1e3), exponential());
  const ContactOperator<2> contact(op, wall, law, geometry.center());

  // A state that penetrates the wall over part of the edge, and a direction.
  auto state = op.create_vector(), direction = op.create_vector();
  dealii::FunctionParser<2> state_function(2), direction_function(2);
  state_function.initialize("x,y", "-0.02 + 0.01*y*y; 0.003*x*y", {});
  direction_function.initialize("x,y", "1 + x*y; 0.5*x", {});
  dealii::VectorTools::interpolate(op.get_mapping(),
                                   op.get_dof_handler(),
                                   state_function,
                                   state);
  dealii::VectorTools::interpolate(op.get_mapping(),
                                   op.get_dof_handler(),
                                   direction_function,
                                   direction);
  op.get_constraints().distribute(state);
  op.get_constraints().distribute(direction);

  auto residual_at = [&](const double s) {
    auto u = state;
    u.add(s, direction);
    auto r = op.create_vector();
    contact.assemble(op.create_ghosted(u), &r, nullptr);
    r.compress(dealii::VectorOperation::add);
    return r;
  };
  auto &tangent     = op.tangent_reset_to_stiffness();
  tangent           = 0.;
  auto       r0     = op.create_vector();
  const auto state0 = contact.assemble(op.create_ghosted(state), &r0, &tangent);
  tangent.compress(dealii::VectorOperation::add);
  REQUIRE(state0.force > 0.);

  // J d against (r(u + h d) - r(u - h d)) / 2h; the penalty residual is
  // piecewise quadratic in h, so central differences are exact up to points
  // that change contact status within +-h (a few, hence the tolerance); the
  // exponential one's error is O(h^2 lambda^2) relative.
  const double h  = 1e-7;
  auto         jd = op.create_vector();
  tangent.vmult(jd, direction);
  auto difference = residual_at(h);
  difference.add(-1., residual_at(-h));
  difference *= 1. / (2 * h);
  auto error = difference;
  error.add(-1., jd);
  CHECK(error.l2_norm() <= 1e-5 * jd.l2_norm());
}

TEST_CASE("log contact law: Lambert-W inverse round trip", "[contact]")
{
  for (const double constant : {-1., -1. - 0.9, -1.7437})
    {
      const Reference::LogContactLaw law(constant);
      for (const double load : {1e-9, 1e-6, 1e-4, 1e-2, 5e-2})
        {
          CAPTURE(constant, load);
          const double d = law.compression(load);
          CHECK(d > 0.);
          CHECK(law.load(d) == Approx(load).epsilon(1e-13));
          CHECK(Reference::LogContactLaw::constant_from(load, d) ==
                Approx(constant).epsilon(1e-12));
        }
      CHECK_THROWS(law.load(1.01 * law.maximum_compression()));
    }
  // delta = P/(pi E2) [ln(4 pi R E2 / P) + C] with R = E2 = 1, P = pi x
  const Reference::LogContactLaw law(-1.3);
  const double                   P = M_PI * 1e-4;
  CHECK(law.compression(1e-4) ==
        Approx(P / M_PI * (std::log(4. * M_PI / P) - 1.3)).epsilon(1e-14));
  CHECK(Reference::hertz_half_width(1e-4) ==
        Approx(std::sqrt(4. * P / M_PI)).epsilon(1e-14));
}
