#include "modal/torsional_modal_analysis.h"

#include "reference/sphere_torsional_modes.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <boost/math/special_functions/legendre.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace DiskImpact
{
  using namespace dealii;

  TorsionalModalAnalysis::TorsionalModalAnalysis(
    const parallel::distributed::Triangulation<2> &triangulation,
    const BodyGeometry                            &geometry,
    const Material                                &material,
    const unsigned int                             fe_degree,
    const ModalSolver                             &solver,
    TimerOutput                                   &timer)
      : geometry(geometry)
      , material(material)
      , solver(solver)
      , timer(timer)
      , op(fe_degree)
  {
    TimerOutput::Scope scope(timer, "torsion: setup");
    op.setup(triangulation, geometry);
  }

  std::vector<ModeResult>
  TorsionalModalAnalysis::run(const unsigned int n_elastic)
  {
    {
      TimerOutput::Scope scope(timer, "torsion: assembly");
      op.assemble(material);
    }
    // Eigenvalues in units of (c_T / R)^2, as for the spheroidal modes.
    const double scale =
      std::pow(material.transverse_wave_speed() / geometry.radius(), 2);
    op.move_constrained_eigenvalues(1e10 * scale);
    ModalBasis basis;
    {
      TimerOutput::Scope scope(timer, "torsion: eigensolver");
      basis = solver.solve(op, n_elastic + 1, -scale);
    }

    TimerOutput::Scope                    scope(timer, "torsion: labelling");
    const Reference::SphereTorsionalModes reference(
      material.transverse_wave_speed(), geometry.radius());
    const unsigned int                   n_max = 8 + n_elastic;
    std::map<unsigned int, unsigned int> found_of_degree;
    std::vector<ModeResult>              modes;
    for (unsigned int i = 0; i < basis.eigenvalues.size(); ++i)
      {
        ModeResult mode;
        mode.index = i;
        mode.omega = basis.omega(i);
        const auto shares =
          degree_shares(op.create_ghosted(basis.modes[i]), n_max);
        const unsigned int n =
          std::max_element(shares.begin(), shares.end()) - shares.begin();
        mode.harmonic_fraction = shares[n];
        // Even about the equator: the odd degrees (P_n^1 has parity
        // (-1)^(n-1)).
        mode.even_order_fraction = 0.;
        for (unsigned int k = 1; k < shares.size(); k += 2)
          mode.even_order_fraction += shares[k];
        // The rigid rotation: an eigenvalue at round-off level.
        if (basis.eigenvalues[i] < 1e-6 * scale)
          mode.label = {n, 0, Reference::ModeFamily::rigid};
        else
          {
            mode.label       = {n,
                                found_of_degree[n]++,
                                Reference::ModeFamily::torsional};
            mode.omega_exact = reference.omega(mode.label);
          }
        modes.push_back(mode);
      }
    return modes;
  }

  std::vector<double>
  TorsionalModalAnalysis::degree_shares(
    const PETScWrappers::MPI::Vector &ghosted_mode,
    const unsigned int                n_max) const
  {
    const QGauss<1>     quadrature(op.degree() + 4);
    FEFaceValues<2>     face_values(op.get_mapping(),
                                op.get_dof_handler().get_fe(),
                                quadrature,
                                update_values | update_quadrature_points |
                                  update_JxW_values);
    std::vector<double> w(quadrature.size());
    // sum over the surface of u_phi P_n^1 sin theta dtheta, and of u_phi^2.
    std::vector<double> moments(n_max + 2, 0.);
    const Point<2>      center = geometry.center();
    const double        R      = geometry.radius();
    for_each_curved_edge_face(
      op.get_dof_handler(), [&](const auto &cell, const unsigned int face) {
        face_values.reinit(cell, face);
        face_values.get_function_values(ghosted_mode, w);
        for (const unsigned int q : face_values.quadrature_point_indices())
          {
            const Tensor<1, 2> d     = face_values.quadrature_point(q) - center;
            const double       theta = std::atan2(d[1], d[0]);
            const double weight      = std::sin(theta) * face_values.JxW(q) / R;
            for (unsigned int n = 1; n <= n_max; ++n)
              moments[n] +=
                w[q] * boost::math::legendre_p(n, 1, std::cos(theta)) * weight;
            moments[n_max + 1] += w[q] * w[q] * weight;
          }
      });
    Utilities::MPI::sum(moments,
                        op.get_dof_handler().get_communicator(),
                        moments);
    // |P_n^1|^2 = 2 n (n + 1) / (2 n + 1) with the weight sin theta.
    std::vector<double> shares(n_max + 1, 0.);
    for (unsigned int n = 1; n <= n_max; ++n)
      {
        const double norm = 2. * n * (n + 1.) / (2. * n + 1.);
        shares[n]         = moments[n] * moments[n] / norm / moments[n_max + 1];
      }
    return shares;
  }
} // namespace DiskImpact
