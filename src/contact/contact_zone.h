#pragma once

#include "base/contact_average.h"
#include "contact/contact.h"
#include "contact/contact_operator.h"

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;

  /**
   * What a contact point carries from one step to the next under Coulomb
   * friction: whether it sticks, its tangential traction along each of the
   * wall's tangents at the step's end, and the length it has slipped so
   * far.
   */
  struct PointHistory
  {
    bool                  sticking = false;
    std::array<double, 2> traction{};
    double                slip = 0.;
  };

  /**
   * The wall contact reduced to the few degrees of freedom it can act on.
   *
   * The candidates are the quadrature points of the edge faces whose
   * undeformed gap is below a bound (the largest approach expected, with a
   * margin), each with its weight ds, its undeformed gap g_0 and its row b:
   * the normal displacement n . u(x_q) = b . u_D in terms of the
   * candidates' DoFs D (hanging-node constraints resolved), replicated on
   * every rank. The gap is g = g_0 + b . u_D.
   *
   * With the law 'constraint' the candidates are the edge nodes instead,
   * each with its share of the edge (the integral of its Lagrange
   * polynomial) as ds, and their forces come from constraint_system().
   *
   * The active DoFs C, a subset of D, are those of the points that have
   * touched the wall: only points with all their DoFs in C carry a force.
   * The step's contact force on C,
   *
   *   P = sum_q ds_q p_bar(g_q(u0_C), g_q(u1_C)) b_q,
   *
   * and its Jacobian dP/du1_C are evaluated without communication.
   */
  class ContactZone
  {
  public:
    /// The candidates: points of edge faces with undeformed gap below
    /// @p gap_bound. With @p with_partner (two dimensions only) the gap is
    /// measured along the wall normal to a collision partner's edge
    /// (locate_on_partner_edge()), and the rows hold both bodies' DoFs.
    /// Collective. @p law: null for the exact constraint. With
    /// @p circular (a sphere in 3D) the contact is a circle about the
    /// contact point: the coordinate along the wall is the distance from
    /// it; else a strip (the plane models, a disk's rim in 3D): the
    /// coordinate along the wall's first tangent.
    template <int dim>
    ContactZone(const ElasticityOperator<dim>    &op,
                const RigidWall<dim>             &wall,
                std::shared_ptr<const ContactLaw> law,
                const dealii::Point<dim>         &body_center,
                double                            gap_bound,
                bool                              with_partner = false,
                bool                              circular     = false);

    /**
     * Coulomb friction with the coefficient @p mu (> 0) at every point: the
     * tangential traction tau, at most mu p, sticks elastically with the
     * law's tangential_stiffness() k_t below that bound and slips at it
     * (docs/theory/friction.md). The tangential DoFs join D. Call before
     * the zone is used.
     */
    void
    enable_friction(double mu);
    /// Whether enable_friction() was called.
    bool
    has_friction() const;

    /**
     * Contact with the body's rigid rotation theta taken exactly (a whole
     * disk in two dimensions): the linear field theta e_z x (x - c) of the
     * displacement moves the edge along tangents, the rotation R(theta)
     * moves it on the circle. The gap and the tangential position of a
     * point gain n . d and t . d with d = (R(theta) - I - theta e_z x)
     * (x - c), so the normal force acts through the current lever arm
     * (docs/theory/friction.md). step_force() and accept_step() then take
     * vectors on C with theta appended, and the force's last entry is the
     * generalized force on theta beyond the linear field's torque.
     */
    void
    enable_rotation();
    /// Whether enable_rotation() was called.
    bool
    tracks_rotation() const;

    /// D, the candidates' DoFs.
    const std::vector<dealii::types::global_dof_index> &
    candidate_dofs() const;

    /**
     * The DoFs (positions in D) of the points that touch the wall (g < 0)
     * in one of the states @p states (values on D) but are not active yet.
     * Throws a RunError if a point in the outer half of the candidates
     * (beyond the law's reach) touches: they might not cover the contact.
     */
    std::vector<unsigned int>
    dofs_to_activate(
      const std::vector<const dealii::Vector<double> *> &states) const;

    /// The smallest gap of the candidates for the values @p u (on D).
    double
    smallest_gap(const dealii::Vector<double> &u) const;

    /// Throws a RunError if a point in the outer half of the candidates
    /// (beyond the law's reach) touches for the values @p u (on D).
    void
    check_within_bound(const dealii::Vector<double> &u) const;

    /// Append the DoFs @p positions (in D) to C, in this order.
    void
    activate(const std::vector<unsigned int> &positions);

    /// |C|.
    unsigned int
    n_active_dofs() const;
    /// C, as positions in D in the order of activation.
    const std::vector<unsigned int> &
    active_dofs() const;

    /// The values on C of @p values_on_D.
    dealii::Vector<double>
    restrict_to_active(const dealii::Vector<double> &values_on_D) const;

    /// The step's force on C (and theta, with tracks_rotation()) and what
    /// it says of the contact.
    struct StepForce
    {
      dealii::Vector<double>     force;    ///< P
      dealii::FullMatrix<double> jacobian; ///< dP / du1_C (if asked for)
      ContactState               state;    ///< at u1; force_average of P
    };

    /**
     * P for a step from @p u0 to @p u1 (values on C), the pressure averaged
     * as @p average (with the weight @p new_weight of the end state if
     * trapezoidal); with @p with_jacobian also dP/du1.
     */
    StepForce
    step_force(const dealii::Vector<double> &u0,
               const dealii::Vector<double> &u1,
               ContactAverage                average,
               double                        new_weight,
               bool                          with_jacobian) const;

    /// Under friction: take the step from @p u0 to @p u1 (values on C),
    /// whose force step_force() gave with @p average and @p new_weight,
    /// into each point's history.
    void
    accept_step(const dealii::Vector<double> &u0,
                const dealii::Vector<double> &u1,
                ContactAverage                average,
                double                        new_weight);

    /// The number of candidate points.
    unsigned int
    n_points() const;
    /// Point @p i's share ds of the surface (dS of its quadrature point, or
    /// a node's share of its faces).
    double
    share(unsigned int i) const;
    /// Point @p i's undeformed coordinate along the wall, from the point of
    /// the wall nearest the body's centre (for a circular contact its
    /// distance from that point within the wall's plane).
    double
    coordinate_along_wall(unsigned int i) const;
    /// Point @p i's tangential row along the wall's tangent @p direction
    /// (RigidWall::tangents()): (global DoF, b_t) with t . u = b_t . u.
    const std::vector<std::pair<dealii::types::global_dof_index, double>> &
    tangential_row(unsigned int i, unsigned int direction = 0) const;
    /// Point @p i's history, to read and to update after a step.
    PointHistory &
    history(unsigned int i);
    const PointHistory &
    history(unsigned int i) const;
    /// Each point's gap row b: (position in D, b).
    std::vector<std::vector<std::pair<unsigned int, double>>>
    point_rows() const;
    /// Each point's gap for the values @p u on D.
    dealii::Vector<double>
    point_gaps(const dealii::Vector<double> &u) const;
    /// The DoFs (positions in D) not yet in C of the points whose entry in
    /// @p mu is not zero.
    std::vector<unsigned int>
    inactive_dofs_of(const dealii::Vector<double> &mu) const;

    /**
     * Law 'constraint': the gaps of the points that can carry a force
     * (all their DoFs in C) as g = gaps + rows du_C, at the values @p u_C
     * on C.
     */
    struct ConstraintSystem
    {
      std::vector<unsigned int>  points; ///< indices of those points
      dealii::FullMatrix<double> rows;   ///< d g / d u_C, one row each
      dealii::Vector<double>     gaps;   ///< g at u_C
    };
    ConstraintSystem
    constraint_system(const dealii::Vector<double> &u_C) const;

    /// sum_q mu_q b_q on C: the force on C of the point forces @p mu (one
    /// per candidate point; zero where it cannot act).
    dealii::Vector<double>
    constraint_force(const dealii::Vector<double> &mu) const;

    /**
     * What the constraint's point forces say of the contact: the step's
     * forces @p mu0 (start) and @p mu1 (end) averaged with the weight
     * @p new_weight of the end, and the end gaps at @p u1 (on C).
     */
    ContactState
    constraint_state(const dealii::Vector<double> &mu0,
                     const dealii::Vector<double> &mu1,
                     const dealii::Vector<double> &u1,
                     double                        new_weight) const;

  private:
    /// One candidate quadrature point.
    struct Point
    {
      double ds;   ///< JxW
      double gap0; ///< undeformed gap
      double t;    ///< coordinate along the wall from the contact point
      /// x - c in the plane of rotation (x, y), c the body's centre.
      std::array<double, 2> from_center;
      std::vector<std::pair<unsigned int, double>> row; ///< (position in D, b)
      /// (position in C, b) once all its DoFs are active, else empty.
      std::vector<std::pair<unsigned int, double>> active_row;
      /// The tangential displacements t . u(x_q) = (global DoF, b_t) . u,
      /// one per tangent t of the wall: the rows of a frictional force
      /// (their DoFs join D when a law uses them).
      std::vector<
        std::vector<std::pair<dealii::types::global_dof_index, double>>>
        tangential_rows;
      /// Under friction the same rows as (position in D, b), and as
      /// (position in C, b) once the point is active.
      std::vector<std::vector<std::pair<unsigned int, double>>>
        tangential_rows_in_D, active_tangential_rows;
      /// What the point carries from step to step.
      PointHistory history;
    };

    /// g of @p point for the values @p u on D.
    static double
    gap(const Point &point, const dealii::Vector<double> &u);

    using Row = std::vector<std::pair<unsigned int, double>>;
    /// A point's motion in a step from u0 to u1 (values on C, theta
    /// appended with tracks_rotation()).
    struct StepKinematics
    {
      double                g0 = 0., g1 = 0.;
      std::array<double, 2> slip_increment{};
      /// d g1 / d u1 and the row the pressure's force acts through (the
      /// two differ in theta's entry: its derivative at theta1 and the
      /// mean slope over the step), per tangent the same for the slip.
      Row               normal_end, normal_force;
      std::array<Row, 2> tangential_end, tangential_force;
      /// d (the force row's theta entry) / d theta1.
      double                normal_curvature = 0.;
      std::array<double, 2> tangential_curvature{};
    };
    StepKinematics
    kinematics(const Point                  &point,
               const dealii::Vector<double> &u0,
               const dealii::Vector<double> &u1) const;
    /// The torque about e_z through the body's centre of a unit force on
    /// @p point along @p direction (in the plane of rotation).
    static double
    lever(const Point &point, const std::array<double, 2> &direction);
    /// The step's mean pressure p_bar and its derivative by g1.
    std::pair<double, double>
    mean_pressure(double         g0,
                  double         g1,
                  ContactAverage average,
                  double         new_weight) const;

    /// A point's friction in a step: its mean traction, the traction at
    /// the step's end, how the mean depends on the end state, and whether
    /// it sticks.
    struct Friction
    {
      std::array<double, 2> mean_traction{};
      std::array<double, 2> traction{};
      bool                  sticking = false;
      /// d mean_traction[d] / d u1 as (position, value) pairs.
      std::array<Row, 2> derivative;
    };
    /// The return mapping of @p point from its history for the step
    /// @p motion with the mean pressure @p p_bar and its derivative
    /// @p dp_bar.
    Friction
    friction(const Point          &point,
             const StepKinematics &motion,
             double                p_bar,
             double                dp_bar,
             double                new_weight,
             bool                  with_derivative) const;
    /// Add @p point's friction force of the step to @p result, with its
    /// Jacobian.
    void
    add_friction(const Point          &point,
                 const StepKinematics &motion,
                 double                p_bar,
                 double                dp_bar,
                 double                new_weight,
                 StepForce            &result,
                 bool                  with_jacobian) const;
    /// The law's reach (0 for the exact constraint).
    double
    reach() const;
    /// The RunError for a touching point beyond the outer half of the
    /// candidates, if @p point is one.
    void
    check_reach(const Point &point) const;

    /// The law (null: the exact constraint).
    std::shared_ptr<const ContactLaw> law;
    /// Coulomb's mu (0: no friction) and the stick stiffness k_t.
    double friction_coefficient = 0., stick_stiffness = 0.;
    /// enable_rotation(), and the wall's normal and first tangent in the
    /// plane of rotation.
    bool                  rotation = false;
    std::array<double, 2> wall_normal{}, wall_tangent{};
    double                            bound;
    /// A sphere's, on its meridian or in 3D (ContactState::axisymmetric).
    bool                                         axisymmetric = false;
    std::vector<dealii::types::global_dof_index> dofs;
    std::vector<Point>                           points;
    /// Position in C of each DoF of D (-1: not active), and C in D.
    std::vector<int>          active_position;
    std::vector<unsigned int> active;
  };
} // namespace DiskImpact
