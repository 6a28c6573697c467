#include "contact/contact_zone.h"

#include "base/input_error.h"
#include "base/run_error.h"
#include "body/geometry.h"
#include "contact/constrained_row.h"
#include "contact/partner_edge.h"
#include "elasticity/elasticity_operator.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// One candidate point as the ranks exchange it.
    template <int dim>
    struct Candidate
    {
      double                                                  ds, gap0, t;
      std::array<double, 2>                                   from_center;
      dealii::Point<dim>                                      x;
      std::vector<std::pair<types::global_dof_index, double>> row;
      std::vector<std::vector<std::pair<types::global_dof_index, double>>>
        tangential;
    };

    /**
     * For each point of @p nodes (the support points of a face, a tensor
     * grid): the integral over the reference face of its Lagrange
     * polynomial, times the Jacobian, as the Gauss rule @p gauss with
     * weights @p weights (JxW times the section's measure) gives it.
     */
    template <int facedim>
    std::vector<double>
    nodal_shares(const Quadrature<facedim> &nodes,
                 const Quadrature<facedim> &gauss,
                 const std::vector<double> &weights)
    {
      // The grid's coordinates along one axis, and their 1D Lagrange basis.
      std::vector<double> coordinates;
      for (const auto &x : nodes.get_points())
        if (std::none_of(coordinates.begin(),
                         coordinates.end(),
                         [&](const double c) {
                           return std::abs(c - x[0]) < 1e-12;
                         }))
          coordinates.push_back(x[0]);
      std::vector<dealii::Point<1>> points_1d;
      for (const double c : coordinates)
        points_1d.emplace_back(c);
      const auto lagrange =
        Polynomials::generate_complete_Lagrange_basis(points_1d);
      const auto index_of = [&](const double c) {
        return std::min_element(coordinates.begin(),
                                coordinates.end(),
                                [&](const double a, const double b) {
                                  return std::abs(a - c) < std::abs(b - c);
                                }) -
               coordinates.begin();
      };
      std::vector<double> shares(nodes.size(), 0.);
      for (unsigned int q = 0; q < nodes.size(); ++q)
        for (unsigned int g = 0; g < gauss.size(); ++g)
          {
            double value = weights[g];
            for (unsigned int d = 0; d < facedim; ++d)
              value *=
                lagrange[index_of(nodes.point(q)[d])].value(gauss.point(g)[d]);
            shares[q] += value;
          }
      return shares;
    }

    /// Merge the candidates at one position (a node shared by faces) into
    /// one point holding all their shares.
    template <int dim>
    void
    merge_shared_nodes(std::vector<Candidate<dim>> &candidates)
    {
      if (candidates.empty())
        return;
      std::sort(candidates.begin(),
                candidates.end(),
                [](const auto &a, const auto &b) { return a.t < b.t; });
      const double tolerance = 1e-9 * std::max(std::abs(candidates.front().t),
                                               std::abs(candidates.back().t));
      std::vector<Candidate<dim>> nodes;
      for (auto &candidate : candidates)
        {
          // Points at one position have t within the tolerance: they are
          // at the end of the sorted list of nodes so far.
          auto same = nodes.rbegin();
          for (; same != nodes.rend() && same->t >= candidate.t - tolerance;
               ++same)
            if (candidate.x.distance(same->x) <= tolerance)
              break;
          if (same != nodes.rend() && same->t >= candidate.t - tolerance)
            same->ds += candidate.ds;
          else
            nodes.push_back(std::move(candidate));
        }
      candidates = std::move(nodes);
    }
  } // namespace

  template <int dim>
  ContactZone::ContactZone(const ElasticityOperator<dim>    &op,
                           const RigidWall<dim>             &wall,
                           std::shared_ptr<const ContactLaw> law,
                           const dealii::Point<dim>         &body_center,
                           const double                      gap_bound,
                           const bool                        with_partner,
                           const bool                        circular)
      : law(std::move(law))
      , bound(gap_bound)
      , axisymmetric(circular || op.get_section().is_axisymmetric())
  {
    const auto &dof_handler = op.get_dof_handler();
    const auto &fe          = dof_handler.get_fe();
    const auto &constraints = op.get_constraints();
    // More points than the element needs for a law: the pressure has a
    // kink where contact ends inside a face. The constraint acts at the
    // edge nodes, each with its share of the edge.
    const bool                nodal = !this->law;
    const QGauss<dim - 1>     gauss(fe.degree + 3);
    const Quadrature<dim - 1> quadrature =
      nodal ?
        Quadrature<dim - 1>(fe.base_element(0).get_unit_face_support_points()) :
        Quadrature<dim - 1>(gauss);
    FEFaceValues<dim>                    face_values(op.get_mapping(),
                                  fe,
                                  quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
    FEFaceValues<dim>                    gauss_values(op.get_mapping(),
                                   fe,
                                   gauss,
                                   update_quadrature_points |
                                     update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    const dealii::Point<dim>             origin =
      body_center - wall.gap(body_center) * wall.normal;
    const auto tangents = wall.tangents();
    wall_normal         = {{wall.normal[0], wall.normal[1]}};
    wall_tangent        = {{tangents[0][0], tangents[0][1]}};
    // The coordinate along the wall: the distance from the origin within
    // the wall's plane for a circle, else signed along the first tangent.
    const auto along_wall = [&](const dealii::Point<dim> &x) {
      const Tensor<1, dim> in_plane =
        (x - origin) - ((x - origin) * wall.normal) * wall.normal;
      return circular ? in_plane.norm() : in_plane * tangents[0];
    };

    // This rank's candidates, flattened for the exchange: ds, g0, t, x - c
    // (x, y), x, the number of entries, then (DoF, b) pairs; the same for
    // each tangential row.
    std::vector<double> local;
    for_each_curved_edge_face(
      dof_handler, [&](const auto &cell, const unsigned int f) {
        face_values.reinit(cell, f);
        const auto &x = face_values.get_quadrature_points();
        if (std::none_of(x.begin(), x.end(), [&](const auto &point) {
              return wall.gap(point) < gap_bound;
            }))
          return;
        cell->get_dof_indices(dof_indices);
        // ds of each point: its JxW, or at a node the integral of its
        // Lagrange polynomial over the face.
        std::vector<double> ds(quadrature.size(), 0.);
        if (nodal)
          {
            gauss_values.reinit(cell, f);
            std::vector<double> weights;
            for (const unsigned int g : gauss_values.quadrature_point_indices())
              weights.push_back(
                gauss_values.JxW(g) *
                op.get_section().measure(gauss_values.quadrature_point(g)));
            ds = nodal_shares(quadrature, gauss, weights);
          }
        else
          for (const unsigned int q : face_values.quadrature_point_indices())
            ds[q] = face_values.JxW(q) *
                    op.get_section().measure(face_values.quadrature_point(q));
        for (const unsigned int q : face_values.quadrature_point_indices())
          {
            ConstrainedRow                      row;
            std::array<ConstrainedRow, dim - 1> tangential;
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const auto phi = face_values[displacement].value(i, q);
                add_to_row(constraints, dof_indices[i], phi * wall.normal, row);
                for (unsigned int d = 0; d < dim - 1; ++d)
                  add_to_row(constraints,
                             dof_indices[i],
                             phi * tangents[d],
                             tangential[d]);
              }
            local.insert(local.end(),
                         {ds[q],
                          wall.gap(x[q]),
                          along_wall(x[q]),
                          x[q][0] - body_center[0],
                          x[q][1] - body_center[1]});
            for (unsigned int d = 0; d < dim; ++d)
              local.push_back(x[q][d]);
            local.push_back(static_cast<double>(row.size()));
            for (const auto &[dof, b] : row)
              local.insert(local.end(), {static_cast<double>(dof), b});
            for (const auto &t_row : tangential)
              {
                local.push_back(static_cast<double>(t_row.size()));
                for (const auto &[dof, b] : t_row)
                  local.insert(local.end(), {static_cast<double>(dof), b});
              }
          }
      });

    // Every rank holds every candidate, in rank order.
    std::vector<Candidate<dim>> candidates;
    for (const auto &part :
         Utilities::MPI::all_gather(dof_handler.get_communicator(), local))
      for (std::size_t k = 0; k < part.size();)
        {
          Candidate<dim> candidate{part[k],
                                   part[k + 1],
                                   part[k + 2],
                                   {{part[k + 3], part[k + 4]}},
                                   {},
                                   {},
                                   {}};
          k += 5;
          for (unsigned int d = 0; d < dim; ++d)
            candidate.x[d] = part[k++];
          candidate.tangential.resize(dim - 1);
          std::vector<decltype(candidate.row) *> rows{&candidate.row};
          for (auto &t_row : candidate.tangential)
            rows.push_back(&t_row);
          for (auto *row : rows)
            {
              const auto n_entries = static_cast<std::size_t>(part[k++]);
              for (std::size_t e = 0; e < n_entries; ++e, k += 2)
                row->emplace_back(static_cast<types::global_dof_index>(part[k]),
                                  part[k + 1]);
            }
          candidates.push_back(std::move(candidate));
        }
    // A node shared by faces is one point with all their shares.
    if (nodal)
      merge_shared_nodes(candidates);
    if (with_partner)
      {
        if constexpr (dim == 2)
          {
            // The gap is measured to the partner's edge, whose normal
            // displacement enters with the opposite sign; points that face
            // no part of it, or face it from beyond the bound, drop out.
            std::vector<dealii::Point<2>> x;
            for (const auto &candidate : candidates)
              x.push_back(candidate.x);
            const auto partner = locate_on_partner_edge(op, wall, x);
            std::vector<Candidate<dim>> paired;
            for (unsigned int k = 0; k < candidates.size(); ++k)
              if (partner[k] && partner[k]->gap0 < gap_bound)
                {
                  Candidate<dim> candidate = std::move(candidates[k]);
                  candidate.gap0           = partner[k]->gap0;
                  candidate.row.insert(candidate.row.end(),
                                       partner[k]->row.begin(),
                                       partner[k]->row.end());
                  paired.push_back(std::move(candidate));
                }
            candidates = std::move(paired);
          }
        else
          throw InputError("a collision partner is two-dimensional so far");
      }

    // D sorted; each point's row in positions of D.
    std::set<types::global_dof_index> all_dofs;
    for (const auto &candidate : candidates)
      for (const auto &entry : candidate.row)
        all_dofs.insert(entry.first);
    dofs.assign(all_dofs.begin(), all_dofs.end());
    for (auto &candidate : candidates)
      {
        Point point{candidate.ds,
                    candidate.gap0,
                    candidate.t,
                    candidate.from_center,
                    {},
                    {},
                    std::move(candidate.tangential),
                    {},
                    {},
                    {}};
        for (const auto &[dof, b] : candidate.row)
          point.row.emplace_back(
            std::lower_bound(dofs.begin(), dofs.end(), dof) - dofs.begin(), b);
        points.push_back(std::move(point));
      }
    active_position.assign(dofs.size(), -1);
  }

  template ContactZone::ContactZone(const ElasticityOperator<2> &,
                                    const RigidWall<2> &,
                                    std::shared_ptr<const ContactLaw>,
                                    const dealii::Point<2> &,
                                    double,
                                    bool,
                                    bool);
  template ContactZone::ContactZone(const ElasticityOperator<3> &,
                                    const RigidWall<3> &,
                                    std::shared_ptr<const ContactLaw>,
                                    const dealii::Point<3> &,
                                    double,
                                    bool,
                                    bool);

  const std::vector<types::global_dof_index> &
  ContactZone::candidate_dofs() const
  {
    return dofs;
  }

  void
  ContactZone::enable_friction(const double mu)
  {
    Assert(law && active.empty(), ExcInternalError());
    friction_coefficient = mu;
    stick_stiffness      = law->tangential_stiffness();
    // D grows by the tangential rows' DoFs; the rows follow D's new order.
    std::set<types::global_dof_index> all_dofs(dofs.begin(), dofs.end());
    for (const Point &point : points)
      for (const auto &row : point.tangential_rows)
        for (const auto &entry : row)
          all_dofs.insert(entry.first);
    const std::vector<types::global_dof_index> old_dofs = dofs;
    dofs.assign(all_dofs.begin(), all_dofs.end());
    const auto position = [&](const types::global_dof_index dof) {
      return static_cast<unsigned int>(
        std::lower_bound(dofs.begin(), dofs.end(), dof) - dofs.begin());
    };
    for (Point &point : points)
      {
        for (auto &entry : point.row)
          entry.first = position(old_dofs[entry.first]);
        point.tangential_rows_in_D.clear();
        for (const auto &row : point.tangential_rows)
          {
            point.tangential_rows_in_D.emplace_back();
            for (const auto &[dof, b] : row)
              point.tangential_rows_in_D.back().emplace_back(position(dof), b);
          }
      }
    active_position.assign(dofs.size(), -1);
  }

  bool
  ContactZone::has_friction() const
  {
    return friction_coefficient > 0.;
  }

  void
  ContactZone::enable_rotation()
  {
    Assert(law, ExcInternalError());
    rotation = true;
  }

  bool
  ContactZone::tracks_rotation() const
  {
    return rotation;
  }

  double
  ContactZone::gap(const Point &point, const Vector<double> &u)
  {
    double g = point.gap0;
    for (const auto &[i, b] : point.row)
      g += b * u[i];
    return g;
  }

  double
  ContactZone::reach() const
  {
    return law ? law->reach() : 0.;
  }

  void
  ContactZone::check_reach(const Point &point) const
  {
    if (point.gap0 > reach() + 0.5 * (bound - reach()))
      throw RunError("the contact reaches edge points whose undeformed "
                     "gap is " +
                     approximately(point.gap0) +
                     ", farther than the contact zone's bound " +
                     approximately(bound) +
                     " foresees (from the 1-DOF model): the collision is "
                     "far from what the model expects");
  }

  double
  ContactZone::smallest_gap(const Vector<double> &u) const
  {
    double smallest = std::numeric_limits<double>::infinity();
    for (const Point &point : points)
      smallest = std::min(smallest, gap(point, u));
    return smallest;
  }

  void
  ContactZone::check_within_bound(const Vector<double> &u) const
  {
    for (const Point &point : points)
      if (gap(point, u) < 0.)
        check_reach(point);
  }

  std::vector<unsigned int>
  ContactZone::dofs_to_activate(
    const std::vector<const Vector<double> *> &states) const
  {
    std::set<unsigned int> missing;
    for (const Point &point : points)
      {
        if (!point.active_row.empty())
          continue;
        for (const auto *u : states)
          if (gap(point, *u) < 0.)
            {
              check_reach(point);
              for (const auto &entry : point.row)
                if (active_position[entry.first] < 0)
                  missing.insert(entry.first);
              for (const auto &row : point.tangential_rows_in_D)
                for (const auto &entry : row)
                  if (active_position[entry.first] < 0)
                    missing.insert(entry.first);
              break;
            }
      }
    return {missing.begin(), missing.end()};
  }

  void
  ContactZone::activate(const std::vector<unsigned int> &positions)
  {
    for (const unsigned int i : positions)
      if (active_position[i] < 0)
        {
          active_position[i] = active.size();
          active.push_back(i);
        }
    const auto all_active = [&](const auto &row) {
      return std::all_of(row.begin(), row.end(), [&](const auto &e) {
        return active_position[e.first] >= 0;
      });
    };
    for (Point &point : points)
      if (point.active_row.empty() && all_active(point.row) &&
          std::all_of(point.tangential_rows_in_D.begin(),
                      point.tangential_rows_in_D.end(),
                      all_active))
        {
          for (const auto &[i, b] : point.row)
            point.active_row.emplace_back(active_position[i], b);
          for (const auto &row : point.tangential_rows_in_D)
            {
              point.active_tangential_rows.emplace_back();
              for (const auto &[i, b] : row)
                point.active_tangential_rows.back().emplace_back(
                  active_position[i], b);
            }
        }
  }

  unsigned int
  ContactZone::n_active_dofs() const
  {
    return active.size();
  }

  const std::vector<unsigned int> &
  ContactZone::active_dofs() const
  {
    return active;
  }

  Vector<double>
  ContactZone::restrict_to_active(const Vector<double> &values_on_D) const
  {
    Vector<double> values(active.size());
    for (unsigned int c = 0; c < active.size(); ++c)
      values[c] = values_on_D[active[c]];
    return values;
  }

  ContactZone::StepKinematics
  ContactZone::kinematics(const Point          &point,
                          const Vector<double> &u0,
                          const Vector<double> &u1) const
  {
    StepKinematics motion;
    motion.g0 = motion.g1 = point.gap0;
    for (const auto &[i, b] : point.active_row)
      {
        motion.g0 += b * u0[i];
        motion.g1 += b * u1[i];
      }
    motion.normal_end = motion.normal_force = point.active_row;
    const unsigned int m = point.active_tangential_rows.size();
    for (unsigned int d = 0; d < m; ++d)
      {
        motion.tangential_end[d] = motion.tangential_force[d] =
          point.active_tangential_rows[d];
        for (const auto &[i, b] : point.active_tangential_rows[d])
          motion.slip_increment[d] += b * (u1[i] - u0[i]);
      }
    if (!rotation)
      return motion;
    // d = (R(theta) - I - theta e_z x) r and its derivatives by theta, with
    // r = x - c; the force acts through the mean slope d'((theta0 +
    // theta1) / 2), exact to O(dtheta^3) for the energy.
    const unsigned int r_pos  = active.size();
    const double       theta0 = u0[r_pos], theta1 = u1[r_pos];
    const auto        &r      = point.from_center;
    const auto         shift  = [&](const double theta,
                           const unsigned int     order,
                           const std::array<double, 2> &direction) {
      const double c = std::cos(theta), s = std::sin(theta);
      std::array<double, 2> d;
      if (order == 0)
        d = {{r[0] * (c - 1.) - r[1] * (s - theta),
              r[0] * (s - theta) + r[1] * (c - 1.)}};
      else if (order == 1)
        d = {{-r[0] * s - r[1] * (c - 1.), r[0] * (c - 1.) - r[1] * s}};
      else
        d = {{-r[0] * c + r[1] * s, -r[0] * s - r[1] * c}};
      return d[0] * direction[0] + d[1] * direction[1];
    };
    const double mid = 0.5 * (theta0 + theta1);
    motion.g0 += shift(theta0, 0, wall_normal);
    motion.g1 += shift(theta1, 0, wall_normal);
    motion.normal_end.emplace_back(r_pos, shift(theta1, 1, wall_normal));
    motion.normal_force.emplace_back(r_pos, shift(mid, 1, wall_normal));
    motion.normal_curvature = 0.5 * shift(mid, 2, wall_normal);
    if (m > 0)
      {
        motion.slip_increment[0] +=
          shift(theta1, 0, wall_tangent) - shift(theta0, 0, wall_tangent);
        motion.tangential_end[0].emplace_back(r_pos,
                                              shift(theta1, 1, wall_tangent));
        motion.tangential_force[0].emplace_back(r_pos,
                                                shift(mid, 1, wall_tangent));
        motion.tangential_curvature[0] = 0.5 * shift(mid, 2, wall_tangent);
      }
    return motion;
  }

  ContactZone::StepForce
  ContactZone::step_force(const Vector<double> &u0,
                          const Vector<double> &u1,
                          const ContactAverage  average,
                          const double          new_weight,
                          const bool            with_jacobian) const
  {
    const unsigned int n = active.size() + (rotation ? 1 : 0);
    StepForce          result;
    result.force.reinit(n);
    if (with_jacobian)
      result.jacobian.reinit(n, n);
    ContactState &state = result.state;
    state.axisymmetric  = axisymmetric;
    for (const Point &point : points)
      {
        if (point.active_row.empty())
          continue;
        const StepKinematics motion = kinematics(point, u0, u1);
        const double         g1     = motion.g1;
        if (motion.g0 >= 0. && g1 >= 0.)
          continue;
        const auto [p_bar, dp_bar] =
          mean_pressure(motion.g0, g1, average, new_weight);
        const double p1 = law->pressure(g1);
        state.force += p1 * point.ds;
        state.force_average += p_bar * point.ds;
        state.energy += law->energy(g1) * point.ds;
        state.second_moment += p1 * point.t * point.t * point.ds;
        state.max_penetration = std::max(state.max_penetration, -g1);
        state.torque_average += p_bar * lever(point, wall_normal) * point.ds;
        for (const auto &[i, b] : motion.normal_force)
          result.force[i] += point.ds * p_bar * b;
        if (rotation)
          state.torque_average +=
            point.ds * p_bar * motion.normal_force.back().second;
        if (with_jacobian && dp_bar != 0.)
          for (const auto &[i, bi] : motion.normal_force)
            for (const auto &[j, bj] : motion.normal_end)
              result.jacobian(i, j) += point.ds * dp_bar * bi * bj;
        if (with_jacobian && rotation)
          result.jacobian(n - 1, n - 1) +=
            point.ds * p_bar * motion.normal_curvature;
        if (has_friction())
          add_friction(
            point, motion, p_bar, dp_bar, new_weight, result, with_jacobian);
      }
    return result;
  }

  ContactZone::Friction
  ContactZone::friction(const Point          &point,
                        const StepKinematics &motion,
                        const double          p_bar,
                        const double          dp_bar,
                        const double          new_weight,
                        const bool            with_derivative) const
  {
    // The step's mean traction tau_bar = (1 - w) tau0 + w tau1 is what
    // moves the body: it sticks as tau0 - w k_t ds (tau1 = tau0 - k_t ds)
    // while |tau0 - w k_t ds| <= mu p_bar, the step's mean pressure, and
    // slips at mu p_bar otherwise (tau1 = tau_bar). A point that leaves the
    // wall ends the step without traction.
    Friction              result;
    const unsigned int    m = point.active_tangential_rows.size();
    std::array<double, 2> trial{};
    double                norm = 0.;
    for (unsigned int d = 0; d < m; ++d)
      {
        trial[d] = point.history.traction[d] -
                   new_weight * stick_stiffness * motion.slip_increment[d];
        norm += trial[d] * trial[d];
      }
    norm               = std::sqrt(norm);
    const double bound = friction_coefficient * p_bar;
    result.sticking    = norm <= bound;
    if (bound <= 0.)
      return result;
    std::array<double, 2> direction{};
    for (unsigned int d = 0; d < m; ++d)
      {
        direction[d] = trial[d] / norm;
        result.mean_traction[d] =
          result.sticking ? trial[d] : bound * direction[d];
        result.traction[d] =
          motion.g1 >= 0. ? 0. :
          result.sticking ?
                            point.history.traction[d] -
                              stick_stiffness * motion.slip_increment[d] :
                            result.mean_traction[d];
      }
    if (!with_derivative)
      return result;
    // Sticking: d tau_bar = -w k_t d(slip). Slipping: the bound's part
    // along the direction e and the direction's part across it.
    const double scale = result.sticking ? 1. : bound / norm;
    for (unsigned int d = 0; d < m; ++d)
      {
        auto &derivative = result.derivative[d];
        for (unsigned int e = 0; e < m; ++e)
          {
            const double projection =
              (d == e ? 1. : 0.) -
              (result.sticking ? 0. : direction[d] * direction[e]);
            if (projection != 0.)
              for (const auto &[i, b] : motion.tangential_end[e])
                derivative.emplace_back(i,
                                        -scale * projection * new_weight *
                                          stick_stiffness * b);
          }
        if (!result.sticking && dp_bar != 0.)
          for (const auto &[i, b] : motion.normal_end)
            derivative.emplace_back(i,
                                    friction_coefficient * dp_bar *
                                      direction[d] * b);
      }
    return result;
  }

  void
  ContactZone::add_friction(const Point          &point,
                            const StepKinematics &motion,
                            const double          p_bar,
                            const double          dp_bar,
                            const double          new_weight,
                            StepForce            &result,
                            const bool            with_jacobian) const
  {
    // The work of the mean traction less the change of the stick's elastic
    // energy |tau|^2 / (2 k_t) is the energy friction dissipates.
    const Friction f =
      friction(point, motion, p_bar, dp_bar, new_weight, with_jacobian);
    const unsigned int m     = point.active_tangential_rows.size();
    const unsigned int n     = result.force.size();
    ContactState      &state = result.state;
    double             work = 0., energy0 = 0., energy1 = 0.;
    for (unsigned int d = 0; d < m; ++d)
      {
        const double tau0    = point.history.traction[d];
        const double tau_bar = f.mean_traction[d];
        for (const auto &[i, b] : motion.tangential_force[d])
          result.force[i] += point.ds * tau_bar * b;
        if (with_jacobian)
          {
            for (const auto &[i, b] : motion.tangential_force[d])
              for (const auto &[j, value] : f.derivative[d])
                result.jacobian(i, j) += point.ds * b * value;
            if (rotation)
              result.jacobian(n - 1, n - 1) +=
                point.ds * tau_bar * motion.tangential_curvature[d];
          }
        state.tangential_force_average[d] += point.ds * tau_bar;
        // The second tangent, e_z in 3D, has no torque about e_z.
        if (d == 0)
          state.torque_average +=
            point.ds * tau_bar *
            (lever(point, wall_tangent) +
             (rotation ? motion.tangential_force[d].back().second : 0.));
        work += tau_bar * motion.slip_increment[d];
        energy0 += tau0 * tau0;
        energy1 += f.traction[d] * f.traction[d];
      }
    energy0 /= 2. * stick_stiffness;
    energy1 /= 2. * stick_stiffness;
    state.energy += point.ds * energy1;
    state.friction_work += point.ds * (-work - (energy1 - energy0));
  }

  void
  ContactZone::accept_step(const Vector<double> &u0,
                           const Vector<double> &u1,
                           const ContactAverage  average,
                           const double          new_weight)
  {
    if (!has_friction())
      return;
    for (Point &point : points)
      {
        if (point.active_row.empty())
          continue;
        const StepKinematics motion = kinematics(point, u0, u1);
        if (motion.g0 >= 0. && motion.g1 >= 0.)
          {
            point.history = {false, {}, point.history.slip};
            continue;
          }
        const auto [p_bar, dp_bar] =
          mean_pressure(motion.g0, motion.g1, average, new_weight);
        const Friction f =
          friction(point, motion, p_bar, dp_bar, new_weight, false);
        // The slip: the tangential displacement the stick's spring did not
        // take up.
        double slip = 0.;
        for (unsigned int d = 0; d < point.active_tangential_rows.size(); ++d)
          slip += std::pow(motion.slip_increment[d] +
                             (f.traction[d] - point.history.traction[d]) /
                               stick_stiffness,
                           2);
        point.history.slip += std::sqrt(slip);
        point.history.traction = f.traction;
        point.history.sticking = f.sticking && motion.g1 < 0.;
      }
  }

  double
  ContactZone::lever(const Point &point, const std::array<double, 2> &direction)
  {
    const auto &r = point.from_center;
    return r[0] * direction[1] - r[1] * direction[0];
  }

  std::pair<double, double>
  ContactZone::mean_pressure(const double         g0,
                             const double         g1,
                             const ContactAverage average,
                             const double         new_weight) const
  {
    if (average == ContactAverage::discrete_gradient)
      return {law->discrete_gradient_pressure(g0, g1),
              law->discrete_gradient_derivative(g0, g1)};
    return {(1. - new_weight) * law->pressure(g0) +
              new_weight * law->pressure(g1),
            new_weight * law->pressure_derivative(g1)};
  }

  unsigned int
  ContactZone::n_points() const
  {
    return points.size();
  }

  double
  ContactZone::share(const unsigned int i) const
  {
    return points[i].ds;
  }

  double
  ContactZone::coordinate_along_wall(const unsigned int i) const
  {
    return points[i].t;
  }

  const std::vector<std::pair<types::global_dof_index, double>> &
  ContactZone::tangential_row(const unsigned int i,
                              const unsigned int direction) const
  {
    return points[i].tangential_rows[direction];
  }

  PointHistory &
  ContactZone::history(const unsigned int i)
  {
    return points[i].history;
  }

  const PointHistory &
  ContactZone::history(const unsigned int i) const
  {
    return points[i].history;
  }

  std::vector<std::vector<std::pair<unsigned int, double>>>
  ContactZone::point_rows() const
  {
    std::vector<std::vector<std::pair<unsigned int, double>>> rows;
    for (const Point &point : points)
      rows.push_back(point.row);
    return rows;
  }

  Vector<double>
  ContactZone::point_gaps(const Vector<double> &u) const
  {
    Vector<double> gaps(points.size());
    for (unsigned int k = 0; k < points.size(); ++k)
      gaps[k] = gap(points[k], u);
    return gaps;
  }

  std::vector<unsigned int>
  ContactZone::inactive_dofs_of(const Vector<double> &mu) const
  {
    std::set<unsigned int> missing;
    for (unsigned int k = 0; k < points.size(); ++k)
      if (mu[k] != 0.)
        for (const auto &entry : points[k].row)
          if (active_position[entry.first] < 0)
            missing.insert(entry.first);
    return {missing.begin(), missing.end()};
  }

  ContactZone::ConstraintSystem
  ContactZone::constraint_system(const Vector<double> &u_C) const
  {
    ConstraintSystem system;
    for (unsigned int k = 0; k < points.size(); ++k)
      if (!points[k].active_row.empty())
        system.points.push_back(k);
    system.rows.reinit(system.points.size(), active.size());
    system.gaps.reinit(system.points.size());
    for (unsigned int r = 0; r < system.points.size(); ++r)
      {
        const Point &point = points[system.points[r]];
        system.gaps[r]     = point.gap0;
        for (const auto &[i, b] : point.active_row)
          {
            system.rows(r, i) += b;
            system.gaps[r] += b * u_C[i];
          }
      }
    return system;
  }

  Vector<double>
  ContactZone::constraint_force(const Vector<double> &mu) const
  {
    Vector<double> force(active.size());
    for (unsigned int k = 0; k < points.size(); ++k)
      if (mu[k] != 0.)
        for (const auto &[i, b] : points[k].active_row)
          force[i] += mu[k] * b;
    return force;
  }

  ContactState
  ContactZone::constraint_state(const Vector<double> &mu0,
                                const Vector<double> &mu1,
                                const Vector<double> &u1,
                                const double          new_weight) const
  {
    ContactState state;
    state.axisymmetric = axisymmetric;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const Point &point = points[k];
        state.force += mu1[k];
        state.force_average += (1. - new_weight) * mu0[k] + new_weight * mu1[k];
        state.second_moment += mu1[k] * point.t * point.t;
        if (!point.active_row.empty())
          {
            double g = point.gap0;
            for (const auto &[i, b] : point.active_row)
              g += b * u1[i];
            state.max_penetration = std::max(state.max_penetration, -g);
          }
      }
    return state;
  }
} // namespace DiskImpact
