#include "modal/modal_projection.h"

#include "body/geometry.h"
#include "elasticity/elasticity_operator.h"
#include "output/csv_table.h"

#include <algorithm>
#include <numeric>

namespace DiskImpact
{
  using namespace dealii;

  ModalProjection::ModalProjection(ElasticityOperator<2> &op,
                                   const BodyGeometry    &geometry,
                                   const double           eigenvalue_scale,
                                   const unsigned int     n_elastic_modes)
  {
    op.move_constrained_eigenvalues(1e10 * eigenvalue_scale);
    const unsigned int n_rigid = geometry.has_symmetry_boundary() ? 1 : 3;
    ModalSolver        solver;
    basis = solver.solve(op, n_rigid + n_elastic_modes, -eigenvalue_scale);

    std::vector<HarmonicContent> harmonics;
    for (const auto &mode : basis.modes)
      harmonics.push_back(compute_boundary_harmonics(
        op, geometry, op.create_ghosted(mode), 8 + n_elastic_modes / 2));
    labels = label_modes(basis.eigenvalues,
                         harmonics,
                         1e-6 * eigenvalue_scale,
                         geometry.has_symmetry_boundary(),
                         coupled_family(geometry));
    while (first_elastic < labels.size() &&
           labels[first_elastic].label.family == Reference::ModeFamily::rigid)
      ++first_elastic;
    energy_time_integral.assign(basis.modes.size(), 0.);
    for (const auto &mode : basis.modes)
      mass_modes.push_back(op.mass_functional(mode));
  }

  std::vector<double>
  ModalProjection::energies(const PETScWrappers::MPI::Vector &u,
                            const PETScWrappers::MPI::Vector &v) const
  {
    std::vector<double> energy(basis.modes.size(), 0.);
    for (unsigned int i = first_elastic; i < basis.modes.size(); ++i)
      {
        const double q     = mass_modes[i] * u;
        const double q_dot = mass_modes[i] * v;
        energy[i] = 0.5 * (q_dot * q_dot + basis.eigenvalues[i] * q * q);
      }
    return energy;
  }

  void
  ModalProjection::add_sample(const PETScWrappers::MPI::Vector &u,
                              const PETScWrappers::MPI::Vector &v,
                              const double                      dt)
  {
    const auto energy = energies(u, v);
    for (unsigned int i = 0; i < energy.size(); ++i)
      energy_time_integral[i] += dt * energy[i];
    sampled_time += dt;
  }

  CsvTable
  ModalProjection::table(const PETScWrappers::MPI::Vector &u,
                         const PETScWrappers::MPI::Vector &v,
                         const double                      reference_energy,
                         const double                      factor) const
  {
    const auto                energy = energies(u, v);
    std::vector<unsigned int> order(energy.size() - first_elastic);
    std::iota(order.begin(), order.end(), first_elastic);
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return energy[a] > energy[b];
                     });
    CsvTable     table({"rank",
                        "n",
                        "l",
                        "family",
                        "omega",
                        "energy_fraction",
                        "average_energy_fraction"});
    const double scale = factor / reference_energy;
    for (unsigned int r = 0; r < order.size(); ++r)
      {
        const unsigned int i = order[r];
        table.start_row();
        table.add(r + 1);
        table.add(labels[i].label.n);
        table.add(labels[i].label.l);
        table.add(to_string(labels[i].label.family));
        table.add(basis.omega(i));
        table.add(scale * energy[i]);
        table.add(sampled_time > 0. ?
                    scale * energy_time_integral[i] / sampled_time :
                    0.);
      }
    return table;
  }
} // namespace DiskImpact
