#include "modal/mode_labelling.h"

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace DiskImpact
{
  using namespace dealii;

  unsigned int
  HarmonicContent::dominant_order() const
  {
    unsigned int best = 0;
    for (unsigned int n = 1; n < radial_power.size(); ++n)
      if (radial_power[n] + tangential_power[n] >
          radial_power[best] + tangential_power[best])
        best = n;
    return best;
  }

  double
  HarmonicContent::dominant_fraction() const
  {
    const double total =
      std::accumulate(radial_power.begin(), radial_power.end(), 0.) +
      std::accumulate(tangential_power.begin(), tangential_power.end(), 0.);
    const unsigned int n = dominant_order();
    return total > 0 ? (radial_power[n] + tangential_power[n]) / total : 0.;
  }

  double
  HarmonicContent::even_order_fraction() const
  {
    double even = 0., total = 0.;
    for (unsigned int n = 0; n < radial_power.size(); ++n)
      {
        const double power = radial_power[n] + tangential_power[n];
        total += power;
        if (n % 2 == 0)
          even += power;
      }
    return total > 0 ? even / total : 0.;
  }

  namespace
  {
    /**
     * Call @p f(angle, u_r, u_angle, d_angle) at every quadrature point of
     * the curved edge of the locally owned cells: angle the polar angle
     * about the centre, u_r and u_angle the polar components of
     * @p displacement, d_angle = ds / R.
     */
    template <typename Function>
    void
    for_each_edge_point(const ElasticityOperator<2>      &op,
                        const BodyGeometry               &geometry,
                        const PETScWrappers::MPI::Vector &displacement,
                        Function                        &&f)
    {
      const unsigned int          degree = op.get_dof_handler().get_fe().degree;
      const QGauss<1>             quadrature(degree + 3);
      FEFaceValues<2>             face_values(op.get_mapping(),
                                  op.get_dof_handler().get_fe(),
                                  quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
      std::vector<Vector<double>> u(quadrature.size(), Vector<double>(2));
      const Point<2>              center = geometry.center();
      for_each_curved_edge_face(
        op.get_dof_handler(), [&](const auto &cell, const unsigned int face) {
          face_values.reinit(cell, face);
          face_values.get_function_values(displacement, u);
          for (const unsigned int q : face_values.quadrature_point_indices())
            {
              const Tensor<1, 2> x = face_values.quadrature_point(q) - center;
              const double       angle = std::atan2(x[1], x[0]);
              const double       c     = std::cos(angle);
              const double       s     = std::sin(angle);
              f(angle,
                u[q][0] * c + u[q][1] * s,
                -u[q][0] * s + u[q][1] * c,
                face_values.JxW(q) / x.norm());
            }
        });
    }

    /// The Legendre content of a sphere's surface displacement
    /// (compute_boundary_harmonics()).
    HarmonicContent
    surface_legendre_content(const ElasticityOperator<2>      &op,
                             const BodyGeometry               &geometry,
                             const PETScWrappers::MPI::Vector &displacement,
                             const unsigned int                n_max)
    {
      const unsigned int n_orders = n_max + 1;
      // Per order: <u_r, P_n>, <u_theta, P_n^1>, <P_n, P_n>, <P_n^1, P_n^1>
      // with weight sin(theta) dtheta; P_n^1 = sin(theta) P_n'(cos theta)
      // is dP_n/dtheta up to its sign.
      std::vector<double> sums(4 * n_orders, 0.);

      for_each_edge_point(op,
                          geometry,
                          displacement,
                          [&](const double theta,
                              const double u_r,
                              const double u_theta,
                              const double dtheta) {
                            const double c      = std::cos(theta);
                            const double weight = std::sin(theta) * dtheta;
                            for (unsigned int n = 0; n < n_orders; ++n)
                              {
                                const double p = std::legendre(n, c);
                                const double p1 =
                                  n > 0 ? std::assoc_legendre(n, 1, c) : 0.;
                                double *out = &sums[4 * n];
                                out[0] += u_r * p * weight;
                                out[1] += u_theta * p1 * weight;
                                out[2] += p * p * weight;
                                out[3] += p1 * p1 * weight;
                              }
                          });
      Utilities::MPI::sum(sums, op.get_dof_handler().get_communicator(), sums);

      HarmonicContent content;
      for (unsigned int n = 0; n < n_orders; ++n)
        {
          const double *in = &sums[4 * n];
          content.radial_power.push_back(in[0] * in[0] / in[2]);
          content.tangential_power.push_back(n > 0 ? in[1] * in[1] / in[3] :
                                                     0.);
        }
      return content;
    }
  } // namespace

  HarmonicContent
  compute_boundary_harmonics(const ElasticityOperator<2>      &op,
                             const BodyGeometry               &geometry,
                             const PETScWrappers::MPI::Vector &displacement,
                             const unsigned int                n_max)
  {
    if (op.get_section().is_axisymmetric())
      return surface_legendre_content(op, geometry, displacement, n_max);

    const unsigned int n_orders = n_max + 1;
    // Per order: <u_r,cos>, <u_r,sin>, <u_phi,cos>, <u_phi,sin>, <cos,cos>,
    // <sin,sin> over the edge, with d(phi) = ds / R.
    std::vector<double> sums(6 * n_orders, 0.);

    for_each_edge_point(op,
                        geometry,
                        displacement,
                        [&](const double phi,
                            const double u_r,
                            const double u_phi,
                            const double dphi) {
                          for (unsigned int n = 0; n < n_orders; ++n)
                            {
                              const double cn  = std::cos(n * phi) * dphi;
                              const double sn  = std::sin(n * phi) * dphi;
                              double      *out = &sums[6 * n];
                              out[0] += u_r * cn;
                              out[1] += u_r * sn;
                              out[2] += u_phi * cn;
                              out[3] += u_phi * sn;
                              out[4] += std::cos(n * phi) * cn;
                              out[5] += std::sin(n * phi) * sn;
                            }
                        });
    Utilities::MPI::sum(sums, op.get_dof_handler().get_communicator(), sums);

    // On the half circle cos(n phi) and sin(m phi) are not orthogonal; the
    // half disk holds only the symmetric part, u_r in cos and u_phi in sin.
    const bool      full_circle = !geometry.has_symmetry_boundary();
    HarmonicContent content;
    for (unsigned int n = 0; n < n_orders; ++n)
      {
        const double *in        = &sums[6 * n];
        auto          cos_power = [&](const double a) { return a * a / in[4]; };
        auto          sin_power = [&](const double b) {
          return n > 0 ? b * b / in[5] : 0.;
        };
        content.radial_power.push_back(cos_power(in[0]) +
                                       (full_circle ? sin_power(in[1]) : 0.));
        content.tangential_power.push_back(
          sin_power(in[3]) + (full_circle ? cos_power(in[2]) : 0.));
      }
    return content;
  }

  std::vector<LabelledMode>
  label_modes(const std::vector<double>          &eigenvalues,
              const std::vector<HarmonicContent> &harmonics,
              const double                        rigid_eigenvalue,
              const bool                          half_domain,
              const Reference::ModeFamily         coupled_family)
  {
    using Reference::ModeFamily;
    const unsigned int orientations = half_domain ? 1 : 2;

    std::map<std::pair<unsigned int, ModeFamily>, unsigned int> seen;
    std::vector<LabelledMode>                                   labelled;
    for (unsigned int i = 0; i < eigenvalues.size(); ++i)
      {
        LabelledMode       mode;
        const auto        &h   = harmonics[i];
        const unsigned int n   = h.dominant_order();
        mode.harmonic_fraction = h.dominant_fraction();
        mode.label.n           = n;
        if (eigenvalues[i] < rigid_eigenvalue)
          mode.label.family = ModeFamily::rigid;
        else if (n == 0)
          mode.label.family = h.radial_power[0] >= h.tangential_power[0] ?
                                ModeFamily::radial :
                                ModeFamily::torsional;
        else
          mode.label.family = coupled_family;

        const unsigned int count = seen[{n, mode.label.family}]++;
        mode.label.l = (n == 0 || mode.label.family == ModeFamily::rigid) ?
                         count :
                         count / orientations;
        labelled.push_back(mode);
      }
    return labelled;
  }
  Reference::ModeFamily
  coupled_family(const BodyGeometry &geometry)
  {
    return geometry.is_axisymmetric() ? Reference::ModeFamily::spheroidal :
                                        Reference::ModeFamily::mixed;
  }
} // namespace DiskImpact
