// Pieces of the impact solver: the condensed solver against the residual of
// the full nonlinear system, the effective matrix, impacts on shared
// operators against impacts on their own, and the 1-DOF log-law collision
// against an independent ODE integration.

#include "body/geometry.h"
#include "dynamics/condensed_solver.h"
#include "dynamics/factorization.h"
#include "elasticity/elasticity_operator.h"
#include "half_disk.h"
#include "impact/impact_estimates.h"
#include "impact/impact_operators.h"
#include "impact/impact_simulation.h"
#include "material/material.h"
#include "reference/log_contact_law.h"
#include "reference/one_dof_impact.h"
#include "run/parameters.h"

#include <deal.II/distributed/tria.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <boost/numeric/odeint.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <string>

using namespace DiskImpact;

namespace
{
  /// The elasticity operator on a half disk (2 refinements, its contact
  /// zone twice refined), assembled for one material (Kelvin-Voigt with a
  /// positive @p relaxation_time).
  struct HalfDiskOperator
  {
    HalfDiskOperator(const unsigned int degree,
                     const PlaneModel   model,
                     const double       nu,
                     const double       relaxation_time = 0.)
        : triangulation(
            MPI_COMM_WORLD,
            dealii::Triangulation<2>::limit_level_difference_at_vertices)
        , op(degree)
    {
      const BodyGeometry geometry = half_disk(2, 2);
      geometry.create_triangulation(triangulation);
      op.setup(triangulation, geometry, true);
      Material material;
      material.set(model, 1., nu, 1., relaxation_time);
      op.assemble(material);
    }
    dealii::parallel::distributed::Triangulation<2> triangulation;
    ElasticityOperator<2>                           op;
  };
} // namespace


TEST_CASE("condensed solver solves A u = b + E_C P(u_C), P nonlinear",
          "[impact][fe]")
{
  HalfDiskOperator half_disk_operator(2, PlaneModel::plane_stress, 0.33);
  auto            &op = half_disk_operator.op;

  auto &A = op.tangent_reset_to_stiffness();
  A *= 0.5;
  A.add(2. / (0.05 * 0.05), op.mass_matrix());
  CondensedSolver solver(A, op.locally_owned_dofs(), MPI_COMM_WORLD);

  // D: eight unconstrained DoFs, C the first six of them.
  std::vector<dealii::types::global_dof_index> observed;
  const auto n = op.get_dof_handler().n_dofs();
  for (unsigned int k = 0; observed.size() < 8; ++k)
    if (!op.get_constraints().is_constrained((37 * k + 11) % n))
      observed.push_back((37 * k + 11) % n);
  solver.set_observed_dofs(observed);
  solver.add_dofs({0, 1, 2});
  solver.add_dofs({3, 4, 5}); // C grows in two parts

  auto b = op.create_vector(), u = op.create_vector(),
       check = op.create_vector();
  for (const auto i : op.locally_owned_dofs())
    if (!op.get_constraints().is_constrained(i))
      b(i) = std::sin(0.37 * i);
  b.compress(dealii::VectorOperation::insert);

  // A stiff one-sided force: P_i = -k <u_i - s_i>, s_i below the free
  // response, so that some but not all of the force is active.
  solver.solve(b, u);
  const auto             y_D = solver.observe(u);
  dealii::Vector<double> y_C(6), s(6);
  for (unsigned int i = 0; i < 6; ++i)
    {
      y_C[i] = y_D[i];
      s[i]   = y_D[i] - (i % 2 == 0 ? 0.1 : -0.1) * std::abs(y_D[i]);
    }
  const double k     = 1e6;
  const auto   force = [&](const dealii::Vector<double> &u_C) {
    dealii::Vector<double>     P(6);
    dealii::FullMatrix<double> dP(6, 6);
    for (unsigned int i = 0; i < 6; ++i)
      if (u_C[i] > s[i])
        {
          P[i]     = -k * (u_C[i] - s[i]);
          dP(i, i) = -k;
        }
    return std::make_pair(P, dP);
  };
  dealii::Vector<double> u_C = y_C;
  unsigned int           iterations;
  INFO("|y_C| = " << y_C.linfty_norm());
  REQUIRE(solver.solve_condensed(
    y_C, force, 1e-10 * y_C.linfty_norm(), 30, u_C, iterations));
  CHECK(iterations <= 10);
  const auto P = force(u_C).first;
  solver.add_columns(P, u);

  // The full residual A u - b - E_C P(u_C), and u on D as predicted.
  A.vmult(check, u);
  check.add(-1., b);
  for (unsigned int i = 0; i < 6; ++i)
    if (op.locally_owned_dofs().is_element(observed[i]))
      check(observed[i]) -= P[i];
  check.compress(dealii::VectorOperation::add);
  CHECK(check.l2_norm() <= 1e-10 * b.l2_norm());
  auto predicted = y_D;
  predicted += solver.observed_response(P);
  const auto u_D = solver.observe(u);
  for (unsigned int i = 0; i < 8; ++i)
    CHECK(std::abs(u_D[i] - predicted[i]) <= 1e-12 * u_D.linfty_norm());
  CHECK(P.l1_norm() > 0.);
  CHECK(solver.n_factorizations() == 1);
  CHECK(solver.n_triangular_solves() == 7); // 6 columns and one solve

  // A stiff linear spring, P = -k_s (u_C - s), puts the residual's
  // rounding floor, about |I + k_s S| eps |u_C|, above a tolerance of
  // 1e-14 |y_C|: Newton stops decreasing it after its first step, but the
  // next step, u_C's error, is within the tolerance, so the solve has
  // converged (the exact solution checks it). A tolerance below even the
  // step's rounding is reported as not met.
  const double k_s    = 1e12;
  const auto   spring = [&](const dealii::Vector<double> &u_C) {
    dealii::Vector<double>     P(6);
    dealii::FullMatrix<double> dP(6, 6);
    for (unsigned int i = 0; i < 6; ++i)
      {
        P[i]     = -k_s * (u_C[i] - s[i]);
        dP(i, i) = -k_s;
      }
    return std::make_pair(P, dP);
  };
  const double y_size = y_C.linfty_norm();
  u_C                 = y_C;
  const bool stiff_done =
    solver.solve_condensed(y_C, spring, 1e-14 * y_size, 30, u_C, iterations);
  dealii::Vector<double> h(6), sp(6);
  solver.condensed_matrix().vmult(sp, spring(u_C).first);
  h = u_C;
  h -= y_C;
  h -= sp;
  INFO("stiff residual " << h.linfty_norm() / y_size << " |y_C|");
  CHECK(stiff_done);
  CHECK(h.linfty_norm() > 1e-14 * y_size);
  // The exact u_C: (I + k_s S) u_C = y_C + k_s S s.
  dealii::LAPACKFullMatrix<double> system(6, 6);
  dealii::Vector<double>           exact(y_C), ks_s(6);
  for (unsigned int i = 0; i < 6; ++i)
    for (unsigned int j = 0; j < 6; ++j)
      system(i, j) = (i == j ? 1. : 0.) + k_s * solver.condensed_matrix()(i, j);
  solver.condensed_matrix().vmult(ks_s, s);
  exact.add(k_s, ks_s);
  system.compute_lu_factorization();
  system.solve(exact);
  for (unsigned int i = 0; i < 6; ++i)
    CHECK(std::abs(u_C[i] - exact[i]) <= 1e-14 * y_size);
  u_C = y_C;
  CHECK_FALSE(
    solver.solve_condensed(y_C, spring, 1e-19 * y_size, 30, u_C, iterations));
}

TEST_CASE("condensed solver in 2x2 blocks solves as the scalar one",
          "[impact][fe]")
{
  // On one rank a block size of 2 factorizes a SeqSBAIJ copy in AMD order
  // (SymmetricBlockCopy); the solution must be that of the scalar
  // factorization and satisfy A u = b to rounding.
  HalfDiskOperator half_disk_operator(3, PlaneModel::plane_strain, 0.45);
  auto            &op = half_disk_operator.op;
  auto            &A  = op.tangent_reset_to_stiffness();
  A.add(1. / (0.05 * 0.05), op.mass_matrix());

  auto b = op.create_vector(), blocked = op.create_vector(),
       scalar = op.create_vector(), residual = op.create_vector();
  for (const auto i : op.locally_owned_dofs())
    if (!op.get_constraints().is_constrained(i))
      b(i) = std::cos(0.71 * i);
  b.compress(dealii::VectorOperation::insert);
  CondensedSolver(A, op.locally_owned_dofs(), MPI_COMM_WORLD, 2)
    .solve(b, blocked);
  CondensedSolver(A, op.locally_owned_dofs(), MPI_COMM_WORLD, 1)
    .solve(b, scalar);

  A.vmult(residual, blocked);
  residual.add(-1., b);
  CHECK(residual.l2_norm() <= 1e-10 * b.l2_norm());
  residual = blocked;
  residual.add(-1., scalar);
  CHECK(residual.linfty_norm() <= 1e-10 * scalar.linfty_norm());
}

TEST_CASE("a refactorized matrix solves as one factorized afresh",
          "[impact][fe]")
{
  // Factorization::refactorize() keeps the block copy's order and the
  // symbolic factorization of the first matrix. For another time step's
  // effective matrix on the same pattern its solution must be that of a
  // factorization made for that matrix alone, in blocks and in scalars,
  // on one rank (PETSc's Cholesky) and on several (MUMPS).
  HalfDiskOperator half_disk_operator(3, PlaneModel::plane_strain, 0.45);
  auto            &op = half_disk_operator.op;
  auto             b = op.create_vector(), refactorized = op.create_vector(),
       afresh = op.create_vector();
  for (const auto i : op.locally_owned_dofs())
    if (!op.get_constraints().is_constrained(i))
      b(i) = std::cos(0.71 * i);
  b.compress(dealii::VectorOperation::insert);
  const auto effective_matrix = [&](const double dt) {
    return MatrixSum{{1., &op.stiffness_matrix()},
                     {1. / (dt * dt), &op.mass_matrix()}};
  };
  for (const unsigned int block_size : {1u, 2u})
    {
      Factorization factorization(effective_matrix(0.05),
                                  MPI_COMM_WORLD,
                                  block_size);
      const auto    A = effective_matrix(0.02);
      factorization.refactorize(A);
      factorization.solve(b, refactorized);
      Factorization(A, MPI_COMM_WORLD, block_size).solve(b, afresh);
      afresh.add(-1., refactorized);
      CHECK(afresh.linfty_norm() <= 1e-13 * refactorized.linfty_norm());
    }
}

TEST_CASE("effective matrix cK K + cM M + cD D from symmetric forms",
          "[impact][fe]")
{
  // A viscous material, so that D is assembled too. The forms are computed
  // on one triangle of each cell matrix and mirrored: K, M and D must be
  // symmetric. The effective matrix as the factorization sums it (into the
  // block copy, or with PETSc's known-pattern MatAXPY) must be what
  // deal.II's general sum gives: its solution has that sum's residual at
  // rounding, and equals that of the sum factorized as one matrix.
  HalfDiskOperator half_disk_operator(3, PlaneModel::plane_strain, 0.3, 0.02);
  auto            &op = half_disk_operator.op;
  REQUIRE(op.has_damping());

  auto x = op.create_vector(), y = op.create_vector(),
       product = op.create_vector();
  for (const auto i : op.locally_owned_dofs())
    {
      x(i) = std::cos(0.37 * i);
      y(i) = std::sin(0.53 * i + 0.2);
    }
  x.compress(dealii::VectorOperation::insert);
  y.compress(dealii::VectorOperation::insert);
  for (const auto *matrix :
       {&op.stiffness_matrix(), &op.mass_matrix(), &op.damping_matrix()})
    {
      matrix->vmult(product, x);
      const double x_y = product * y;
      matrix->vmult(product, y);
      CHECK(std::abs(x_y - product * x) <= 1e-13 * std::abs(x_y));
    }

  const double c_K = 0.5, c_M = 1. / (0.05 * 0.05), c_D = 0.5 / 0.05;
  dealii::PETScWrappers::MPI::SparseMatrix sum;
  sum.reinit(op.stiffness_matrix());
  sum.copy_from(op.stiffness_matrix());
  sum *= c_K;
  sum.add(c_M, op.mass_matrix());
  sum.add(c_D, op.damping_matrix());
  const MatrixSum terms{{c_K, &op.stiffness_matrix()},
                        {c_M, &op.mass_matrix()},
                        {c_D, &op.damping_matrix(), SAME_NONZERO_PATTERN}};
  auto            b = op.create_vector(), solution = op.create_vector();
  for (const auto i : op.locally_owned_dofs())
    if (!op.get_constraints().is_constrained(i))
      b(i) = std::cos(0.71 * i);
  b.compress(dealii::VectorOperation::insert);
  auto of_the_sum = op.create_vector();
  for (const unsigned int block_size : {1u, 2u})
    {
      Factorization(terms, MPI_COMM_WORLD, block_size).solve(b, solution);
      sum.vmult(product, solution);
      product.add(-1., b);
      CHECK(product.linfty_norm() <= 1e-10 * b.linfty_norm());
      Factorization(sum, MPI_COMM_WORLD, block_size).solve(b, of_the_sum);
      of_the_sum.add(-1., solution);
      CHECK(of_the_sum.linfty_norm() <= 1e-13 * solution.linfty_norm());
    }
}

TEST_CASE("impacts on shared operators equal impacts on their own",
          "[impact][fe]")
{
  // A convergence study's runs on one mesh share its operators and differ
  // in the time step only. Each run writes the effective matrix for its own
  // step: a run after another one on the same operators must give what it
  // gives on its own, to rounding.
  dealii::ParameterHandler prm;
  Parameters::declare_parameters(prm);
  prm.parse_input_from_string(R"(
set Task = impact
subsection Geometry
  set Domain = half disk
end
subsection Finite element
  set Degree = 2
end
subsection Impact
  set Velocity                = 0.1
  set Elements across contact = 4
  set Number of projected modes = 0
end
subsection Time stepping
  set Time step fraction = 0.02
end
)");
  Parameters coarse;
  coarse.parse_parameters(prm);
  Parameters fine      = coarse;
  fine.time_integrator = coarse.time_integrator.with_time_step_scaled(0.5);

  const auto own_coarse = run_impact(coarse, MPI_COMM_SELF, false);
  const auto own_fine   = run_impact(fine, MPI_COMM_SELF, false);
  REQUIRE(own_fine.steps > own_coarse.steps);

  const auto shared = make_impact_operators(coarse, MPI_COMM_SELF);
  for (const auto *run : {&coarse, &fine, &coarse})
    {
      const auto &own       = run == &fine ? own_fine : own_coarse;
      const auto  on_shared = run_impact(*run, MPI_COMM_SELF, false, shared);
      CAPTURE(run == &fine);
      CHECK(on_shared.steps == own.steps);
      CHECK(on_shared.n_dofs == own.n_dofs);
      CHECK(std::abs(on_shared.epsilon - own.epsilon) <= 1e-13);
      CHECK(std::abs(on_shared.contact_time - own.contact_time) <=
            1e-13 * own.contact_time);
    }
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

TEST_CASE("a plastic sphere's approach bound: Y's pressure over a^2 = R delta",
          "[impact]")
{
  // m v^2 / 2 = pi R Y delta^2 / 2: delta = v sqrt(m / (pi R Y)), with
  // m = 4/3 pi R^3 rho and v in units of c = sqrt(E2 / rho).
  const auto parameters_for = [](const std::string &material) {
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.parse_input_from_string("set Task = impact\n"
                                "subsection Geometry\n"
                                "  set Body = sphere\n"
                                "end\n"
                                "subsection Impact\n"
                                "  set Velocity = 0.001\n"
                                "end\n"
                                "subsection Material\n" +
                                material + "end\n");
    Parameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  };
  const Parameters plastic =
    parameters_for("  set Poisson ratio = 0.3\n  set Yield stress = 0.002\n");
  const double c = plastic.material.velocity_unit();
  const double v = 0.001 * c, mass = 4. / 3. * M_PI;
  CHECK(plastic_approach_bound(plastic) ==
        Approx(v * std::sqrt(mass / (M_PI * 0.002))).epsilon(1e-12));
  CHECK(plastic_approach_bound(parameters_for("")) == 0.);
}
