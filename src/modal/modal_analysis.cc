#include "modal/modal_analysis.h"

#include "base/run_error.h"
#include "output/atomic_file.h"
#include "output/csv_table.h"
#include "output/vtu_record.h"
#include "reference/free_disk_modes.h"
#include "reference/free_sphere_modes.h"

#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/data_out.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  std::unique_ptr<Reference::FreeBodyModes>
  analytic_free_modes(const BodyGeometry &geometry, const Material &material)
  {
    if (geometry.body() == Body::sphere)
      return std::make_unique<Reference::FreeSphereModes>(
        material.poisson_ratio(),
        material.longitudinal_wave_speed(),
        geometry.radius());
    return std::make_unique<Reference::FreeDiskModes>(
      material.in_plane_poisson_ratio(),
      material.longitudinal_wave_speed(),
      geometry.radius());
  }

  bool
  ModeResult::is_rigid() const
  {
    return label.family == Reference::ModeFamily::rigid;
  }

  double
  ModeResult::relative_error() const
  {
    return omega / omega_exact - 1.;
  }

  ModalAnalysis::ModalAnalysis(const BodyGeometry &geometry,
                               const Material     &material,
                               unsigned int        fe_degree,
                               const ModalSolver  &solver,
                               MPI_Comm            communicator,
                               TimerOutput        &timer)
      : geometry(geometry)
      , material(material)
      , solver(solver)
      , communicator(communicator)
      , timer(timer)
      , triangulation(communicator,
                      Triangulation<2>::limit_level_difference_at_vertices)
      , op(fe_degree)
  {
    TimerOutput::Scope scope(timer, "mesh and setup");
    geometry.create_triangulation(triangulation);
    op.setup(triangulation, geometry);
  }

  types::global_dof_index
  ModalAnalysis::n_dofs() const
  {
    return op.get_dof_handler().n_dofs();
  }

  const parallel::distributed::Triangulation<2> &
  ModalAnalysis::get_triangulation() const
  {
    return triangulation;
  }

  double
  ModalAnalysis::mesh_size() const
  {
    return GridTools::maximal_cell_diameter(triangulation, op.get_mapping());
  }

  unsigned int
  ModalAnalysis::n_cells() const
  {
    return triangulation.n_global_active_cells();
  }

  std::vector<ModeResult>
  ModalAnalysis::run(const unsigned int n_elastic)
  {
    const double scale =
      assemble_eigenproblem(op, material, geometry.radius(), timer);

    const unsigned int n_rigid = geometry.has_symmetry_boundary() ? 1 : 3;
    {
      TimerOutput::Scope scope(timer, "eigensolver");
      basis = solver.solve(op, n_rigid + n_elastic + 1, -scale);
    }

    TimerOutput::Scope           scope(timer, "labelling");
    std::vector<HarmonicContent> harmonics;
    const unsigned int           n_max_order = 8 + n_elastic / 2;
    for (const auto &mode : basis.modes)
      harmonics.push_back(compute_boundary_harmonics(
        op, geometry, op.create_ghosted(mode), n_max_order));
    const auto labels = label_modes(basis.eigenvalues,
                                    harmonics,
                                    1e-6 * scale,
                                    geometry.has_symmetry_boundary(),
                                    coupled_family(geometry));

    const auto              reference = analytic_free_modes(geometry, material);
    std::vector<ModeResult> modes;
    unsigned int            n_elastic_found = 0;
    for (unsigned int i = 0; i < labels.size(); ++i)
      {
        ModeResult mode;
        mode.index               = i;
        mode.omega               = basis.omega(i);
        mode.label               = labels[i].label;
        mode.harmonic_fraction   = labels[i].harmonic_fraction;
        mode.even_order_fraction = harmonics[i].even_order_fraction();
        if (!mode.is_rigid())
          {
            mode.omega_exact = reference->omega(mode.label);
            // Keep the extra mode only if it completes the last pair.
            if (n_elastic_found == n_elastic &&
                !(mode.label == modes.back().label))
              break;
            ++n_elastic_found;
          }
        modes.push_back(mode);
      }
    return modes;
  }

  void
  ModalAnalysis::write_modes_csv(const std::vector<ModeResult> &modes,
                                 const std::string             &filename,
                                 const bool                     with_z_parity)
  {
    std::vector<std::string> columns{"index",
                                     "omega",
                                     "n",
                                     "l",
                                     "family",
                                     "omega_exact",
                                     "relative_error",
                                     "boundary_harmonic_fraction"};
    if (with_z_parity)
      columns.push_back("z_parity");
    CsvTable table(columns);
    for (const auto &mode : modes)
      {
        table.start_row();
        table.add(mode.index);
        table.add(mode.omega);
        table.add(mode.label.n);
        if (mode.is_rigid())
          {
            table.add_empty();
            table.add(to_string(mode.label.family));
            table.add_empty();
            table.add_empty();
          }
        else
          {
            table.add(mode.label.l);
            table.add(to_string(mode.label.family));
            table.add(mode.omega_exact);
            table.add(mode.relative_error());
          }
        table.add(mode.harmonic_fraction);
        if (with_z_parity)
          table.add(
            std::string(mode.even_order_fraction > 0.5 ? "even" : "odd"));
      }
    table.write(filename);
  }

  void
  ModalAnalysis::write_mode_shapes(const std::vector<ModeResult> &modes,
                                   const std::string &directory) const
  {
    std::vector<unsigned int> indices;
    for (const auto &mode : modes)
      indices.push_back(mode.index);
    DiskImpact::write_mode_shapes(op, basis, indices, directory);
  }

  void
  ModalAnalysis::print_table(const std::vector<ModeResult> &modes,
                             ConditionalOStream            &out)
  {
    std::ostringstream s;
    s << " mode   n   l  family          omega (FE)       omega (exact) "
         "   rel. error\n";
    for (const auto &mode : modes)
      {
        s << std::setw(5) << mode.index << std::setw(4) << mode.label.n;
        if (mode.is_rigid())
          s << "   -  " << std::left << std::setw(10) << "rigid" << std::right
            << std::scientific << std::setprecision(3) << std::setw(17)
            << mode.omega << '\n';
        else
          s << std::setw(4) << mode.label.l << "  " << std::left
            << std::setw(10) << to_string(mode.label.family) << std::right
            << std::fixed << std::setprecision(12) << std::setw(17)
            << mode.omega << std::setw(21) << mode.omega_exact
            << std::scientific << std::setprecision(2) << std::setw(13)
            << mode.relative_error() << '\n';
        s.unsetf(std::ios_base::floatfield);
      }
    out << s.str();
  }
} // namespace DiskImpact
