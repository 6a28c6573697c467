// Pieces of the impact solver: the low-rank corrected solver against the
// residual of the corrected system, and the 1-DOF log-law collision against
// an independent ODE integration.

#include "body/geometry.h"
#include "dynamics/low_rank_corrected_solver.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/material.h"
#include "reference/log_contact_law.h"
#include "reference/one_dof_impact.h"

#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <boost/numeric/odeint.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace DiskImpact;

TEST_CASE("low-rank corrected solver solves (A + sum w b b^T) x = r",
          "[impact][fe]")
{
  dealii::ParameterHandler prm;
  DiskGeometry::declare_parameters(prm);
  prm.enter_subsection("Geometry");
  prm.set("Domain", "half disk");
  prm.set("Global refinements", "2");
  prm.set("Contact refinements", "2");
  prm.leave_subsection();
  DiskGeometry geometry;
  geometry.parse_parameters(prm);
  dealii::parallel::distributed::Triangulation<2> triangulation(
    MPI_COMM_WORLD,
    dealii::Triangulation<2>::limit_level_difference_at_vertices);
  geometry.create_triangulation(triangulation);
  ElasticityOperator op(2);
  op.setup(triangulation, geometry, true);
  Material material;
  material.set(PlaneModel::plane_stress, 1., 0.33, 1.);
  op.assemble(material);

  auto &A = op.tangent_reset_to_stiffness();
  A *= 0.5;
  A.add(2. / (0.05 * 0.05), op.mass_matrix());
  LowRankCorrectedSolver solver(A, op.locally_owned_dofs(), MPI_COMM_WORLD);

  // Rank-one terms on a few unconstrained DoFs, stiff as a penalty.
  std::vector<RankOneTerm> terms;
  const auto               n = op.get_dof_handler().n_dofs();
  for (unsigned int t = 0; t < 6; ++t)
    {
      RankOneTerm term;
      term.weight = 1e6 * (t + 1);
      for (unsigned int k = 0; k < 4; ++k)
        {
          const auto dof = (37 * t + 11 * k) % n;
          if (!op.get_constraints().is_constrained(dof))
            term.entries.emplace_back(dof, 1. + 0.3 * k - 0.1 * t);
        }
      terms.push_back(term);
    }
  auto r = op.create_vector(), x = op.create_vector(),
       check = op.create_vector();
  for (const auto i : op.locally_owned_dofs())
    if (!op.get_constraints().is_constrained(i))
      r(i) = std::sin(0.37 * i);
  r.compress(dealii::VectorOperation::insert);

  for (unsigned int round = 0; round < 2; ++round) // the second reuses X
    {
      solver.solve(terms, r, x);
      A.vmult(check, x);
      for (const auto &term : terms)
        {
          double bx = 0.;
          for (const auto &[i, b] : term.entries)
            bx += b * x(i);
          for (const auto &[i, b] : term.entries)
            check(i) += term.weight * b * bx;
        }
      check.compress(dealii::VectorOperation::add);
      check.add(-1., r);
      CAPTURE(round);
      CHECK(check.l2_norm() <= 1e-9 * r.l2_norm());
    }
  CHECK(solver.n_factorizations() == 1);
  CHECK(solver.n_contact_dofs() <= 24);
}

TEST_CASE("1-DOF log-law collision against an ODE integration", "[impact]")
{
  // m delta'' = -P(delta), integrated with Boost.Odeint's Dormand-Prince
  // until delta returns to zero: contact time and largest compression.
  const double C = -1.7437, E2 = 1.3, R = 0.8, mass = M_PI * R * R * 2.;
  for (const double v : {1e-3, 1e-2, 0.1})
    {
      const auto reference = Reference::one_dof_impact(v, mass, E2, R, C);
      const Reference::LogContactLaw law(C);
      using State = std::array<double, 2>;
      auto rhs    = [&](const State &s, State &ds, double) {
        ds[0] = s[1];
        ds[1] = s[0] > 0. ? -M_PI * E2 * R * law.load(s[0] / R) / mass : 0.;
      };
      auto stepper = boost::numeric::odeint::make_dense_output(
        1e-12, 1e-12, boost::numeric::odeint::runge_kutta_dopri5<State>());
      State  s{{1e-300, v}};
      double delta_max = 0.;
      stepper.initialize(s, 0., 1e-3 * reference.contact_time);
      // Zero crossing of component k of the dense output in the last step.
      auto crossing = [&](const unsigned int k) {
        double lo = stepper.previous_time(), hi = stepper.current_time();
        for (int i = 0; i < 60; ++i)
          {
            State      x;
            const auto mid = 0.5 * (lo + hi);
            stepper.calc_state(mid, x);
            (x[k] > 0. ? lo : hi) = mid;
          }
        return lo;
      };
      while (stepper.current_state()[0] > 0.)
        {
          stepper.do_step(rhs);
          if (stepper.current_state()[1] <= 0. && delta_max == 0.)
            {
              State x;
              stepper.calc_state(crossing(1), x);
              delta_max = x[0];
            }
        }
      const double lo = crossing(0);
      CAPTURE(v);
      CHECK(reference.contact_time == Approx(lo).epsilon(1e-6));
      CHECK(reference.max_compression == Approx(delta_max).epsilon(1e-6));
    }
}
