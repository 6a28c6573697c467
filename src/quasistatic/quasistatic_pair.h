#pragma once

#include "contact/contact_zone.h"
#include "dynamics/condensed_solver.h"
#include "elasticity/elasticity_operator.h"
#include "reference/two_body_contact.h"

#include <deal.II/distributed/tria.h>

#include <deal.II/lac/petsc_vector.h>

#include <mpi.h>

#include <array>
#include <memory>
#include <string>
#include <utility>

namespace DiskImpact
{
  struct Parameters;

  /// One converged state of two bodies pressed together, lengths in units
  /// of the body's radius R.
  struct PairContactPoint
  {
    /// P / (pi E2 R) (disks), P / (pi E* R^2) (spheres), the body's E and R.
    double load = 0.;
    /// The approach of the two centres of mass.
    double approach = 0.;
    /// Each body's share: its contact centre's displacement toward the
    /// other body relative to its centre of mass (body, partner).
    std::array<double, 2> shares{{0., 0.}};
    double                half_width    = 0.; ///< a from the pressure moments
    double                penetration   = 0.; ///< deepest overlap
    double                force_balance = 0.; ///< int p ds / P - 1
    double                h_contact     = 0.; ///< smallest edge face
    unsigned int          n_dofs        = 0;
    unsigned int          newton_iterations = 0;
  };

  /**
   * Two bodies (subsection Partner) pressed together head-on by equal and
   * opposite uniform body forces of total P, the two-body version of the
   * quasistatic wall problem (docs/theory/two-body-law.md): each body
   * decelerated by its contact with the other.
   *
   * Each body is free to translate along the axis, so K is singular. The
   * far pole of each body is held (x-displacement zero) and the body's
   * rigid translation s relative to the partner is an unknown of its own:
   * u = w + s t, t the body's uniform translation along the axis, w the
   * solution of the pinned problem K w = f + E_C P(u_C). The pins carry no
   * force when the contact force on the body equals its body force, which
   * is the equation that goes with s. With the condensed solver (C = all
   * contact candidates, w_C = y_C + S P):
   *
   *   u_C - y_C - S P(u_C) - s t_C = 0,   t_C . P(u_C) = P,
   *
   * solved by Newton's method with a backtracking line search.
   */
  class QuasistaticPair
  {
  public:
    QuasistaticPair(const Parameters &parameters,
                    double            load,
                    MPI_Comm          communicator);

    /// Newton from the body translated toward the partner until the
    /// deepest overlap is Hertz's a^2 / (2 R_eff); returns the iterations.
    unsigned int
    solve(double tolerance, unsigned int max_iterations);

    PairContactPoint
    results() const;

    /// Hertz's half-width (disks) or contact radius (spheres) of the pair.
    double
    hertz_half_width() const;
    /// P in absolute units (per unit thickness for disks).
    double
    force() const;
    /// The two bodies as the two-body law sees them (Impact::contact_bodies()).
    const std::pair<Reference::ContactBody, Reference::ContactBody> &
    bodies() const;

    /// The deformed state of both bodies with stresses; returns the .pvtu's
    /// name.
    std::string
    write_state(const std::string &directory, unsigned int index) const;

  private:
    /// The residual of the condensed system at (u_C, s), and its Jacobian
    /// if @p jacobian is not null; returns the contact state at u_C.
    ContactState
    residual(const dealii::Vector<double> &u_C,
             double                        s,
             dealii::Vector<double>       &r,
             dealii::FullMatrix<double>   *jacobian) const;
    /// max |r_i| over the displacement scale, |r_P| (relative force).
    double
    residual_norm(const dealii::Vector<double> &r) const;

    const Parameters                                               &parameters;
    const double                                                    load;
    const std::pair<Reference::ContactBody, Reference::ContactBody> pair;
    const double                                                    total_force;
    const double domain_force;
    /// 1 / (1 / R1 + 1 / R2).
    const double                                    effective_radius;
    double                                          a_hertz        = 0.;
    double                                          approach_scale = 0.;
    MPI_Comm                                        communicator;
    dealii::parallel::distributed::Triangulation<2> triangulation;
    ElasticityOperator<2>                           op;
    double                                          h_contact = 0.;
    std::unique_ptr<ContactZone>                    zone;
    std::unique_ptr<CondensedSolver>                solver;
    /// The body's uniform translation along the axis, t.
    dealii::PETScWrappers::MPI::Vector translation;
    /// y = K^{-1} f and the solution u = y + X P + s t.
    dealii::PETScWrappers::MPI::Vector y, solution;
    /// y_C and t_C (S is the solver's condensed_matrix()).
    dealii::Vector<double> y_C, t_C;
    unsigned int           iterations = 0;
  };
} // namespace DiskImpact
