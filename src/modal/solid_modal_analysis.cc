#include "modal/solid_modal_analysis.h"

#include "body/solid_geometry.h"
#include "output/csv_table.h"
#include "reference/free_sphere_modes.h"
#include "reference/sphere_torsional_modes.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  bool
  SolidModeResult::is_rigid() const
  {
    return label.family == Reference::ModeFamily::rigid;
  }

  double
  SolidModeResult::relative_error() const
  {
    return omega_exact > 0. ? omega / omega_exact - 1. : 0.;
  }

  SolidModalAnalysis::SolidModalAnalysis(const BodyGeometry &geometry,
                                         const Material     &material,
                                         const unsigned int  fe_degree,
                                         const ModalSolver  &solver,
                                         MPI_Comm            communicator,
                                         TimerOutput        &timer)
      : geometry(geometry)
      , material(material)
      , solver(solver)
      , timer(timer)
      , triangulation(communicator)
      , op(fe_degree)
  {
    TimerOutput::Scope scope(timer, "mesh and setup");
    create_solid_triangulation(geometry, triangulation);
    op.setup(triangulation, geometry);
  }

  types::global_dof_index
  SolidModalAnalysis::n_dofs() const
  {
    return op.get_dof_handler().n_dofs();
  }

  unsigned int
  SolidModalAnalysis::n_cells() const
  {
    return triangulation.n_global_active_cells();
  }

  double
  SolidModalAnalysis::radial_fraction(
    const PETScWrappers::MPI::Vector &ghosted_mode) const
  {
    // Over the volume: a torsional mode u = j_n(k r) x x grad Y has no
    // radial component anywhere, a spheroidal one has, if little at the
    // surface.
    const auto               &fe = op.get_dof_handler().get_fe();
    const QGauss<3>           quadrature(fe.degree + 1);
    FEValues<3>               fe_values(op.get_mapping(),
                          fe,
                          quadrature,
                          update_values | update_quadrature_points |
                            update_JxW_values);
    std::vector<Tensor<1, 3>> u(quadrature.size());
    const Point<3>            center(geometry.radius(), 0., 0.);
    double                    radial = 0., total = 0.;
    for (const auto &cell : op.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Vector(0)].get_function_values(
            ghosted_mode, u);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Tensor<1, 3> r    = fe_values.quadrature_point(q) - center;
              const double       norm = r.norm();
              const double       u_r  = norm > 0. ? u[q] * r / norm : 0.;
              radial += u_r * u_r * fe_values.JxW(q);
              total += u[q] * u[q] * fe_values.JxW(q);
            }
        }
    const MPI_Comm comm = op.get_dof_handler().get_communicator();
    return Utilities::MPI::sum(radial, comm) / Utilities::MPI::sum(total, comm);
  }

  void
  SolidModalAnalysis::label(std::vector<SolidModeResult> &modes) const
  {
    const double rho = material.density();
    const double c_L =
      std::sqrt(material.stiffness_tensor<3>()[0][0][0][0] / rho);
    const double c_T =
      std::sqrt(material.stiffness_tensor<3>()[0][1][0][1] / rho);
    const Reference::FreeSphereModes      spheroidal(material.poisson_ratio(),
                                                c_L,
                                                geometry.radius());
    const Reference::SphereTorsionalModes torsional(c_T, geometry.radius());
    // Clusters of equal frequencies among the elastic modes, in order.
    std::map<std::pair<Reference::ModeFamily, unsigned int>, unsigned int>
      overtones;
    for (std::size_t first = 0; first < modes.size();)
      {
        if (modes[first].is_rigid())
          {
            ++first;
            continue;
          }
        std::size_t end = first + 1;
        while (end < modes.size() && modes[end].omega - modes[end - 1].omega <
                                       cluster_tolerance * modes[end - 1].omega)
          ++end;
        const unsigned int multiplicity   = end - first;
        double             largest_radial = 0.;
        for (std::size_t i = first; i < end; ++i)
          largest_radial = std::max(largest_radial, modes[i].radial_fraction);
        Reference::ModeLabel label;
        label.n      = (multiplicity - 1) / 2;
        label.family = largest_radial < torsional_radial_fraction ?
                         Reference::ModeFamily::torsional :
                         Reference::FreeSphereModes::family(label.n);
        const bool labelled =
          multiplicity % 2 == 1 &&
          !(label.family == Reference::ModeFamily::torsional && label.n == 0);
        if (labelled)
          label.l = overtones[{label.family, label.n}]++;
        const double exact = !labelled ? 0. :
                             label.family == Reference::ModeFamily::torsional ?
                                         torsional.omega(label) :
                                         spheroidal.omega(label);
        for (std::size_t i = first; i < end; ++i)
          {
            modes[i].label        = label;
            modes[i].multiplicity = multiplicity;
            modes[i].labelled     = labelled;
            modes[i].omega_exact  = exact;
          }
        first = end;
      }
  }

  std::vector<SolidModeResult>
  SolidModalAnalysis::run(const unsigned int n_elastic)
  {
    const double scale =
      assemble_eigenproblem(op, material, geometry.radius(), timer);
    // Beyond the modes asked for, enough to complete a multiplet of degree
    // up to 10.
    constexpr unsigned int n_rigid = 6, n_completing = 21;
    {
      TimerOutput::Scope scope(timer, "eigensolver");
      basis = solver.solve(op, n_rigid + n_elastic + n_completing, -scale);
    }

    TimerOutput::Scope           scope(timer, "labelling");
    std::vector<SolidModeResult> modes(basis.modes.size());
    for (unsigned int i = 0; i < modes.size(); ++i)
      {
        modes[i].index = i;
        modes[i].omega = basis.omega(i);
        if (basis.eigenvalues[i] < 1e-6 * scale)
          modes[i].label.family = Reference::ModeFamily::rigid;
        else
          modes[i].radial_fraction =
            radial_fraction(op.create_ghosted(basis.modes[i]));
      }
    // A sphere's modes are labelled against Lamb's; a disk's are not.
    if (geometry.is_sphere())
      label(modes);
    else
      for (auto &mode : modes)
        mode.labelled = false;
    const auto rigid = static_cast<std::size_t>(
      std::count_if(modes.begin(), modes.end(), [](const auto &mode) {
        return mode.is_rigid();
      }));
    // The modes asked for, and the rest of the last one's multiplet; a
    // multiplet cut by the end of the computed modes is left out.
    std::size_t keep = std::min<std::size_t>(rigid + n_elastic, modes.size());
    while (keep < modes.size() && keep > 0 &&
           modes[keep].omega - modes[keep - 1].omega <
             cluster_tolerance * modes[keep - 1].omega)
      ++keep;
    AssertThrow(keep < modes.size(),
                ExcMessage("the last multiplet exceeds the modes computed"));
    modes.resize(keep);
    return modes;
  }

  void
  SolidModalAnalysis::write_mode_shapes(
    const std::vector<SolidModeResult> &modes,
    const std::string                  &directory) const
  {
    std::vector<unsigned int> indices;
    for (const auto &mode : modes)
      indices.push_back(mode.index);
    DiskImpact::write_mode_shapes(op, basis, indices, directory);
  }

  void
  SolidModalAnalysis::write_modes_csv(const std::vector<SolidModeResult> &modes,
                                      const std::string &filename)
  {
    CsvTable table({"index",
                    "omega",
                    "n",
                    "l",
                    "family",
                    "multiplicity",
                    "omega_exact",
                    "relative_error",
                    "radial_fraction"});
    for (const auto &mode : modes)
      {
        table.start_row();
        table.add(mode.index);
        table.add(mode.omega);
        if (mode.is_rigid() || !mode.labelled)
          {
            table.add_empty();
            table.add_empty();
            table.add(std::string(mode.is_rigid() ? "rigid" : "unlabelled"));
            table.add(mode.multiplicity);
            table.add_empty();
            table.add_empty();
          }
        else
          {
            table.add(mode.label.n);
            table.add(mode.label.l);
            table.add(to_string(mode.label.family));
            table.add(mode.multiplicity);
            table.add(mode.omega_exact);
            table.add(mode.relative_error());
          }
        table.add(mode.radial_fraction);
      }
    table.write(filename);
  }

  void
  SolidModalAnalysis::print_table(const std::vector<SolidModeResult> &modes,
                                  ConditionalOStream                 &out)
  {
    std::ostringstream text;
    text << "  modes      family        n   l  omega          Lamb's omega"
            "    largest rel. error\n";
    for (std::size_t first = 0; first < modes.size();)
      {
        // One line per multiplet (all rigid modes on one); a mode of
        // multiplicity 1 (a disk's modes are not clustered) on its own.
        std::size_t end = first + 1;
        while (end < modes.size() &&
               modes[end].is_rigid() == modes[first].is_rigid() &&
               (modes[first].is_rigid() ||
                (modes[first].multiplicity > 1 &&
                 modes[end].label == modes[first].label &&
                 modes[end].multiplicity == modes[first].multiplicity)))
          ++end;
        double largest_error = 0.;
        for (std::size_t i = first; i < end; ++i)
          largest_error =
            std::max(largest_error, std::abs(modes[i].relative_error()));
        const auto &mode = modes[first];
        text << std::setw(4) << first << "-" << std::left << std::setw(5)
             << end - 1 << std::right << std::setw(12)
             << (mode.is_rigid() ? "rigid" :
                 !mode.labelled  ? "unlabelled" :
                                   to_string(mode.label.family));
        if (mode.is_rigid() || !mode.labelled)
          text << std::scientific << std::setprecision(6) << std::setw(35)
               << mode.omega << '\n';
        else
          text << std::setw(5) << mode.label.n << std::setw(4) << mode.label.l
               << std::scientific << std::setprecision(8) << std::setw(17)
               << mode.omega << std::setw(17) << mode.omega_exact
               << std::setprecision(2) << std::setw(12) << largest_error
               << '\n';
        first = end;
      }
    out << text.str();
  }
} // namespace DiskImpact
