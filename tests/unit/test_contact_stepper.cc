// The time step on its own (ContactStepper): the energy and the impulse of
// single steps, a step that cuts against steps of the halved size, and the
// condensed contact solve against a direct solve of the full system.

#include "body/geometry.h"
#include "contact/contact.h"
#include "contact/contact_operator.h"
#include "contact/contact_zone.h"
#include "dynamics/contact_stepper.h"
#include "dynamics/time_integrator.h"
#include "elasticity/constraint_map.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/interleaved_mass.h"
#include "half_disk.h"
#include "material/material.h"

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

using namespace DiskImpact;

namespace
{
  /// A half disk (Q2, plane stress, nu = 0.3, E = rho = R = 1) touching
  /// the wall x = 0 at its contact point, with the penalty law and what a
  /// stepper is built from.
  struct SteppingBody
  {
    explicit SteppingBody(const std::string &scheme,
                          const unsigned int max_newton_iterations = 30)
        : triangulation(
            MPI_COMM_WORLD,
            dealii::Triangulation<2>::limit_level_difference_at_vertices)
        , op(2)
    {
      const BodyGeometry geometry = half_disk(1, 3);
      geometry.create_triangulation(triangulation);
      op.setup(triangulation, geometry);
      Material material;
      material.set(PlaneModel::plane_stress, 1., 0.3, 1., 0.);
      op.assemble(material);
      constraint_map = std::make_unique<ConstraintMap>(op.get_constraints(),
                                                       op.locally_owned_dofs(),
                                                       MPI_COMM_WORLD);
      mass_product   = std::make_unique<InterleavedMass>(op.mass_matrix(),
                                                       op.get_constraints(),
                                                       *constraint_map);
      dealii::ParameterHandler prm;
      TimeIntegrator::declare_parameters(prm);
      prm.enter_subsection("Time stepping");
      prm.set("Scheme", scheme);
      prm.set("Maximum Newton iterations",
              std::to_string(max_newton_iterations));
      prm.leave_subsection();
      integrator.parse_parameters(prm);

      ContactParameters::declare_parameters(prm);
      ContactParameters contact;
      contact.parse_parameters(prm);
      law = contact.law(
        {material.in_plane_young_modulus(), smallest_edge_face(op), 1.});
      wall   = contact.wall();
      center = geometry.center();

      along_normal = op.create_vector();
      dealii::VectorTools::interpolate(op.get_mapping(),
                                       op.get_dof_handler(),
                                       dealii::Functions::ConstantFunction<2>(
                                         std::vector<double>{1., 0.}),
                                       along_normal);
      op.get_constraints().distribute(along_normal);
    }

    /// A contact zone with the candidates within 0.1 R of the wall.
    std::unique_ptr<ContactZone>
    zone() const
    {
      return std::make_unique<ContactZone>(op, wall, law, center, 0.1);
    }

    /// A stepper on @p zone, its contact solved to 1e-13 of 0.01 R.
    std::unique_ptr<ContactStepper<2>>
    stepper(ContactZone &zone)
    {
      return std::make_unique<ContactStepper<2>>(op,
                                                 *constraint_map,
                                                 *mass_product,
                                                 zone,
                                                 integrator,
                                                 false,
                                                 factorization,
                                                 0.01,
                                                 MPI_COMM_WORLD);
    }

    /// The uniform velocity -v toward the wall.
    dealii::PETScWrappers::MPI::Vector
    approaching(const double v) const
    {
      auto velocity = op.create_vector();
      velocity.add(-v, along_normal);
      return velocity;
    }

    /// x^T A x / 2 with the constrained entries of x zeroed.
    double
    quadratic_form(const dealii::PETScWrappers::MPI::SparseMatrix &A,
                   const dealii::PETScWrappers::MPI::Vector       &x) const
    {
      auto zeroed = op.create_vector(), product = op.create_vector();
      constraint_map->zeroed(x, zeroed);
      A.vmult(product, zeroed);
      return 0.5 * (zeroed * product);
    }

    dealii::parallel::distributed::Triangulation<2> triangulation;
    ElasticityOperator<2>                           op;
    std::unique_ptr<ConstraintMap>                  constraint_map;
    std::unique_ptr<InterleavedMass>                mass_product;
    TimeIntegrator                                  integrator;
    std::shared_ptr<const ContactLaw>               law;
    RigidWall<2>                                    wall;
    dealii::Point<2>                                center;
    dealii::PETScWrappers::MPI::Vector              along_normal;
    std::shared_ptr<Factorization>                  factorization;
  };

  /// The speed and step of the tests: v = 0.02 (in c), about 40 steps of
  /// contact.
  constexpr double speed = 0.02, step = 0.1;
} // namespace

TEST_CASE("a step conserves energy and its impulse is the momentum change",
          "[stepper][fe]")
{
  // The energy-conserving scheme: kinetic + strain + contact energy after a
  // step equal to before; the centre of mass's momentum changes by dt times
  // the step's mean force (the rigid translation is in K's kernel). Both to
  // rounding: the contact solve stops at 1e-15 R on the contact DoFs, and
  // sums over all DoFs lose a few 1e-16 each (measured: 3.5e-14 and
  // 1.4e-13 at most).
  SteppingBody body("energy conserving");
  auto         zone    = body.zone();
  auto         stepper = body.stepper(*zone);
  stepper->start(body.approaching(speed), step);
  const auto momentum_functional = body.op.mass_functional(body.along_normal);

  const auto energy = [&](const ContactState &state) {
    return body.quadratic_form(body.op.mass_matrix(), stepper->velocity()) +
           body.quadratic_form(body.op.stiffness_matrix(),
                               stepper->displacement()) +
           state.energy;
  };
  const double initial    = energy(ContactState());
  double       before     = initial;
  unsigned int in_contact = 0;
  for (unsigned int n = 0; n < 30; ++n)
    {
      const double momentum = momentum_functional * stepper->velocity();
      const auto   result   = stepper->advance(step);
      REQUIRE(result.converged);
      REQUIRE(result.cuts == 0);
      REQUIRE(result.dt == step);
      const double after = energy(result.state);
      CHECK(std::abs(after - before) <= 1e-12 * initial);
      const double change =
        momentum_functional * stepper->velocity() - momentum;
      CHECK(std::abs(change - step * result.state.force_average) <=
            1e-12 * std::abs(momentum));
      in_contact += result.state.force_average > 0.;
      before = after;
    }
  CHECK(in_contact >= 20);
  CHECK(stepper->time() == Approx(30 * step));
}

TEST_CASE("a step that cuts equals steps of the sizes it took", "[stepper][fe]")
{
  // With six Newton iterations allowed (the steps of this impact take five
  // to eight), some steps fail and are halved (and refactorized) until
  // Newton converges within six. A second
  // stepper, Newton unrestricted, takes steps of the sizes the first one
  // took: the states agree to rounding (the failed attempts may have
  // activated more DoFs, whose forces are zero; measured: identical).
  SteppingBody cut("energy conserving", 6);
  auto         cut_zone    = cut.zone();
  auto         cut_stepper = cut.stepper(*cut_zone);
  cut_stepper->start(cut.approaching(speed), step);
  std::vector<double> steps;
  unsigned int        cuts = 0;
  double              dt   = step;
  while (cut_stepper->time() < 1.)
    {
      const auto result = cut_stepper->advance(dt);
      REQUIRE(result.converged);
      CHECK(result.dt == dt / std::pow(2., result.cuts));
      cuts += result.cuts;
      dt = result.dt;
      steps.push_back(dt);
    }
  REQUIRE(cuts > 0);
  CHECK(dt < step);
  CHECK(cut_stepper->n_factorizations() == 1 + cuts);

  SteppingBody replay("energy conserving");
  auto         zone    = replay.zone();
  auto         stepper = replay.stepper(*zone);
  stepper->start(replay.approaching(speed), step);
  for (const double size : steps)
    REQUIRE(stepper->advance(size).converged);
  CHECK(stepper->time() == cut_stepper->time());
  auto difference = stepper->displacement();
  difference.add(-1., cut_stepper->displacement());
  CHECK(difference.linfty_norm() <=
        1e-12 * stepper->displacement().linfty_norm());
}

TEST_CASE("a step that cannot converge leaves the state as it was",
          "[stepper][fe]")
{
  // One Newton iteration and no cuts allowed: the first step into the wall
  // fails, and the stepper says so without changing its state.
  SteppingBody             body("energy conserving");
  dealii::ParameterHandler prm;
  TimeIntegrator::declare_parameters(prm);
  prm.enter_subsection("Time stepping");
  prm.set("Maximum Newton iterations", "1");
  prm.set("Maximum step cuts", "0");
  prm.leave_subsection();
  body.integrator.parse_parameters(prm);
  auto       zone     = body.zone();
  auto       stepper  = body.stepper(*zone);
  const auto velocity = body.approaching(speed);
  stepper->start(velocity, step);
  const auto result = stepper->advance(step);
  CHECK_FALSE(result.converged);
  CHECK(stepper->time() == 0.);
  CHECK(stepper->displacement().linfty_norm() == 0.);
  auto difference = stepper->velocity();
  difference.add(-1., velocity);
  CHECK(difference.linfty_norm() == 0.);
}

TEST_CASE("the condensed contact solve equals a direct solve of the full "
          "system",
          "[stepper][fe]")
{
  // One trapezoidal (Newmark) step from rest-in-shape at v toward the wall:
  // (cm M + K / 2) u1 = cm dt M v + E P(u1), P the step's contact force on
  // the candidates' DoFs. Solved here by Newton's method on all DoFs with
  // dense LU factorizations, against the stepper's condensed solve. Both
  // solve to rounding (the stepper to 1e-15 R on the contact DoFs, the
  // dense Newton until its update is 1e-13 of u; measured: 4e-15 apart).
  SteppingBody body("newmark");
  auto         zone    = body.zone();
  auto         stepper = body.stepper(*zone);
  const auto   v       = body.approaching(speed);
  const double dt      = 4. * step; // several points come into contact
  stepper->start(v, dt);
  const auto result = stepper->advance(dt);
  REQUIRE(result.converged);
  REQUIRE(result.state.force_average > 0.);

  // The full system, densely.
  const auto        &op = body.op;
  const unsigned int n  = op.get_dof_handler().n_dofs();
  REQUIRE(n < 3000);
  const auto                &integrator = body.integrator;
  dealii::FullMatrix<double> A(n, n);
  for (const auto &[matrix, weight] : std::vector<
         std::pair<const dealii::PETScWrappers::MPI::SparseMatrix *, double>>{
         {&op.stiffness_matrix(), integrator.stiffness_coefficient()},
         {&op.mass_matrix(), integrator.mass_coefficient(dt)}})
    for (unsigned int r = 0; r < n; ++r)
      for (auto entry = matrix->begin(r); entry != matrix->end(r); ++entry)
        A(r, entry->column()) += weight * entry->value();
  // b = cm dt M v (u0 = a0 = 0), constrained entries of v zeroed.
  auto zeroed = op.create_vector(), mass_v = op.create_vector();
  body.constraint_map->zeroed(v, zeroed);
  op.mass_matrix().vmult(mass_v, zeroed);
  dealii::Vector<double> b(n);
  for (unsigned int i = 0; i < n; ++i)
    b[i] = integrator.mass_coefficient(dt) * dt * mass_v[i];

  // Every candidate active: C = D.
  auto                      full_zone = body.zone();
  const auto               &D         = full_zone->candidate_dofs();
  std::vector<unsigned int> all(D.size());
  std::iota(all.begin(), all.end(), 0u);
  full_zone->activate(all);
  const dealii::Vector<double> u0_C(D.size());

  dealii::Vector<double> u(n), residual(n), du(n);
  for (unsigned int iteration = 0;; ++iteration)
    {
      REQUIRE(iteration < 30);
      dealii::Vector<double> u_C(D.size());
      for (unsigned int k = 0; k < D.size(); ++k)
        u_C[k] = u[D[k]];
      const auto force = full_zone->step_force(u0_C,
                                               u_C,
                                               integrator.contact_average(),
                                               integrator.contact_new_weight(),
                                               true);
      // F(u) = A u - b - E P, J = A - E dP/du_C E^T.
      A.vmult(residual, u);
      residual -= b;
      dealii::LAPACKFullMatrix<double> J(n, n);
      J = A;
      for (unsigned int k = 0; k < D.size(); ++k)
        {
          residual[D[k]] -= force.force[k];
          for (unsigned int l = 0; l < D.size(); ++l)
            J(D[k], D[l]) -= force.jacobian(k, l);
        }
      J.compute_lu_factorization();
      du = residual;
      J.solve(du);
      u -= du;
      if (du.linfty_norm() <= 1e-13 * u.linfty_norm())
        break;
    }
  auto direct = op.create_vector();
  for (unsigned int i = 0; i < n; ++i)
    direct[i] = u[i];
  direct.compress(dealii::VectorOperation::insert);
  body.constraint_map->distribute(direct);

  auto difference = direct;
  difference.add(-1., stepper->displacement());
  CHECK(difference.linfty_norm() <= 1e-12 * direct.linfty_norm());
}

TEST_CASE("contact points carry the tangential displacement and a history",
          "[stepper][contact][fe]")
{
  // t . u at each candidate point from its tangential row, for u = (0, y)
  // (t = (0, 1) on the wall x = 0; it satisfies the symmetry line's
  // u_y = 0, and the isoparametric elements hold it exactly): y at the
  // point, its coordinate along the wall. For u = n = (1, 0): zero. The
  // history starts at rest and keeps what is written to it.
  SteppingBody              body("energy conserving");
  auto                      zone  = body.zone();
  auto                      shear = body.op.create_vector();
  dealii::FunctionParser<2> shear_function(2);
  shear_function.initialize("x,y", "0; y", {});
  dealii::VectorTools::interpolate(body.op.get_mapping(),
                                   body.op.get_dof_handler(),
                                   shear_function,
                                   shear);
  REQUIRE(zone->n_points() > 0);
  for (unsigned int i = 0; i < zone->n_points(); ++i)
    {
      double along_t = 0., along_n = 0.;
      for (const auto &[dof, b] : zone->tangential_row(i))
        {
          along_t += b * shear[dof];
          along_n += b * body.along_normal[dof];
        }
      CHECK(along_t == Approx(zone->coordinate_along_wall(i)).margin(1e-13));
      CHECK(std::abs(along_n) <= 1e-13);
      CHECK_FALSE(zone->history(i).sticking);
      CHECK(zone->history(i).slip == 0.);
    }
  zone->history(0).slip = 0.25;
  CHECK(zone->history(0).slip == 0.25);
}

TEST_CASE("a refactorized stepper goes on as before", "[stepper][fe]")
{
  // refactorize() rebuilds the factorization and K u from the operator's
  // matrices, for a material whose stiffness changed. With K unchanged the
  // steps after it equal those of a stepper that did not refactorize, to
  // rounding (K u by a product instead of the step's linear system).
  SteppingBody plain("energy conserving"), refreshed("energy conserving");
  auto         plain_zone = plain.zone(), refreshed_zone = refreshed.zone();
  auto a = plain.stepper(*plain_zone), b = refreshed.stepper(*refreshed_zone);
  a->start(plain.approaching(speed), step);
  b->start(refreshed.approaching(speed), step);
  for (unsigned int n = 0; n < 20; ++n)
    {
      if (n == 10)
        b->refactorize();
      REQUIRE(a->advance(step).converged);
      REQUIRE(b->advance(step).converged);
    }
  CHECK(b->n_factorizations() == a->n_factorizations() + 1);
  auto difference = a->displacement();
  difference.add(-1., b->displacement());
  CHECK(difference.linfty_norm() <= 1e-10 * a->displacement().linfty_norm());
}

TEST_CASE("the operator keeps its law's state at every quadrature point",
          "[material][fe]")
{
  // Q2 elements, QGauss(3): nine states per locally owned cell, made by the
  // body's law (linear elastic here), kept by a second assembly.
  SteppingBody body("energy conserving");
  auto        &states = body.op.quadrature_point_states();
  CHECK_FALSE(body.op.constitutive_law().is_viscous());
  std::vector<const QuadraturePointState *> first;
  for (const auto &cell : body.triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &state : states.get_data(cell))
        first.push_back(state.get());
  CHECK(first.size() == 9 * body.triangulation.n_locally_owned_active_cells());
  Material material;
  material.set(PlaneModel::plane_stress, 1., 0.3, 1., 0.);
  body.op.assemble(material);
  unsigned int k = 0;
  for (const auto &cell : body.triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &state : states.get_data(cell))
        CHECK(state.get() == first[k++]);
}
