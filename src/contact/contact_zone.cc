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
    // The coordinate along the wall: the distance from the origin within
    // the wall's plane for a circle, else signed along the first tangent.
    const auto along_wall = [&](const dealii::Point<dim> &x) {
      const Tensor<1, dim> in_plane =
        (x - origin) - ((x - origin) * wall.normal) * wall.normal;
      return circular ? in_plane.norm() : in_plane * tangents[0];
    };

    // This rank's candidates, flattened for the exchange: ds, g0, t, x,
    // the number of entries, then (DoF, b) pairs; the same for each
    // tangential row.
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
                         {ds[q], wall.gap(x[q]), along_wall(x[q])});
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
          Candidate<dim> candidate{
            part[k], part[k + 1], part[k + 2], {}, {}, {}};
          k += 3;
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
                    {},
                    {},
                    std::move(candidate.tangential),
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
    for (Point &point : points)
      if (point.active_row.empty() &&
          std::all_of(point.row.begin(), point.row.end(), [&](const auto &e) {
            return active_position[e.first] >= 0;
          }))
        for (const auto &[i, b] : point.row)
          point.active_row.emplace_back(active_position[i], b);
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

  ContactZone::StepForce
  ContactZone::step_force(const Vector<double> &u0,
                          const Vector<double> &u1,
                          const ContactAverage  average,
                          const double          new_weight,
                          const bool            with_jacobian) const
  {
    const unsigned int n = active.size();
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
        double g0 = point.gap0, g1 = point.gap0;
        for (const auto &[i, b] : point.active_row)
          {
            g0 += b * u0[i];
            g1 += b * u1[i];
          }
        if (g0 >= 0. && g1 >= 0.)
          continue;
        double p_bar, dp_bar;
        if (average == ContactAverage::discrete_gradient)
          {
            p_bar  = law->discrete_gradient_pressure(g0, g1);
            dp_bar = law->discrete_gradient_derivative(g0, g1);
          }
        else
          {
            p_bar = (1. - new_weight) * law->pressure(g0) +
                    new_weight * law->pressure(g1);
            dp_bar = new_weight * law->pressure_derivative(g1);
          }
        const double p1 = law->pressure(g1);
        state.force += p1 * point.ds;
        state.force_average += p_bar * point.ds;
        state.energy += law->energy(g1) * point.ds;
        state.second_moment += p1 * point.t * point.t * point.ds;
        state.max_penetration = std::max(state.max_penetration, -g1);
        for (const auto &[i, b] : point.active_row)
          result.force[i] += point.ds * p_bar * b;
        if (with_jacobian && dp_bar != 0.)
          for (const auto &[i, bi] : point.active_row)
            for (const auto &[j, bj] : point.active_row)
              result.jacobian(i, j) += point.ds * dp_bar * bi * bj;
      }
    return result;
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
