#include "base/run_error.h"
#include "modal/modal_analysis.h"
#include "modal/solid_modal_analysis.h"
#include "modal/torsional_modal_analysis.h"
#include "output/csv_table.h"
#include "reference/sphere_torsional_modes.h"
#include "run/parameters.h"
#include "run/task_registry.h"
#include "tasks/run_checks.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iostream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The analytic modes @p labels of @p reference in their own order.
    void
    write_analytic_modes(const Reference::FreeBodyModes          &reference,
                         const std::vector<Reference::ModeLabel> &labels,
                         const std::string                       &filename)
    {
      CsvTable table({"index", "omega", "n", "l", "family"});
      for (unsigned int i = 0; i < labels.size(); ++i)
        {
          table.start_row();
          table.add(i);
          table.add(reference.omega(labels[i]));
          table.add(labels[i].n);
          table.add(labels[i].l);
          table.add(to_string(labels[i].family));
        }
      table.write(filename);
    }

    /**
     * The computed @p modes (rigid ones first) against @p reference: the
     * analytic modes in their own order to @p filename, and on the terminal
     * the largest relative error and how many leading labels equal the
     * analytic ordering.
     */
    void
    compare_with_analytic(const std::vector<ModeResult>  &modes,
                          const Reference::FreeBodyModes &reference,
                          const bool                      half_domain,
                          const std::string              &filename,
                          MPI_Comm                        communicator,
                          ConditionalOStream             &pcout)
    {
      unsigned int n_rigid   = 0;
      double       max_error = 0.;
      for (const auto &mode : modes)
        if (mode.is_rigid())
          ++n_rigid;
        else
          max_error = std::max(max_error, std::abs(mode.relative_error()));
      const auto analytic =
        reference.lowest_modes(modes.size() - n_rigid, half_domain);
      unsigned int n_matching = 0;
      while (n_matching < analytic.size() &&
             modes[n_rigid + n_matching].label == analytic[n_matching])
        ++n_matching;
      on_root(communicator,
              [&]() { write_analytic_modes(reference, analytic, filename); });
      pcout << n_rigid << " rigid-body modes, " << modes.size() - n_rigid
            << " elastic modes, largest relative error " << max_error
            << "\nLabels equal to the analytic ordering: first " << n_matching
            << " of " << analytic.size() << " elastic modes" << std::endl;
    }

    /// A sphere's torsional modes on the mesh of @p analysis:
    /// torsional_modes.csv, their table and their comparison with Lamb's.
    void
    run_torsional_modes(const Parameters    &parameters,
                        const ModalAnalysis &analysis,
                        MPI_Comm             communicator,
                        TimerOutput         &timer,
                        ConditionalOStream  &pcout)
    {
      TorsionalModalAnalysis torsion(analysis.get_triangulation(),
                                     parameters.geometry,
                                     parameters.material,
                                     parameters.finite_element.degree,
                                     parameters.modal_solver,
                                     timer);
      const auto             modes =
        torsion.run(parameters.modal_solver.n_torsional_modes());
      const std::string &directory = parameters.run.output_directory;
      on_root(communicator, [&]() {
        ModalAnalysis::write_modes_csv(modes,
                                       directory + "/torsional_modes.csv",
                                       true);
      });
      pcout << "Torsional modes (u_phi only):\n";
      ModalAnalysis::print_table(modes, pcout);
      compare_with_analytic(modes,
                            Reference::SphereTorsionalModes(
                              parameters.material.transverse_wave_speed(),
                              parameters.geometry.radius()),
                            false,
                            directory + "/torsional_analytic_modes.csv",
                            communicator,
                            pcout);
    }
  } // namespace

  namespace
  {
    /**
     * Task 'modal analysis': the lowest modes of the free disk, labelled and
     * compared with the analytic Bessel modes. Writes modes.csv,
     * analytic_modes.csv and the mode shapes (modes.pvd), prints the table.
     */
    /**
     * Task 'modal analysis' of a body in three dimensions: its modes,
     * labelled from their shapes, against Lamb's. Writes modes.csv and the
     * mode shapes (modes.pvd), prints one line per multiplet.
     */
    void
    run_solid_modal_analysis(const Parameters &parameters,
                             MPI_Comm          communicator)
    {
      ConditionalOStream pcout(std::cout,
                               Utilities::MPI::this_mpi_process(communicator) ==
                                 0);
      TimerOutput timer(pcout, TimerOutput::never, TimerOutput::wall_times);
      SolidModalAnalysis analysis(parameters.geometry,
                                  parameters.material,
                                  parameters.finite_element.degree,
                                  parameters.modal_solver,
                                  communicator,
                                  timer);
      pcout << "Mesh: " << parameters.geometry.description() << ", "
            << analysis.n_cells() << " cells, "
            << analysis.n_dofs() << " DoFs (Q"
            << parameters.finite_element.degree << ", mapping of degree "
            << parameters.finite_element.degree << ")" << std::endl;
      const auto modes =
        analysis.run(parameters.modal_solver.n_elastic_modes());
      {
        TimerOutput::Scope scope(timer, "output");
        analysis.write_mode_shapes(modes, parameters.run.output_directory);
        on_root(communicator, [&]() {
          SolidModalAnalysis::write_modes_csv(modes,
                                              parameters.run.output_directory +
                                                "/modes.csv");
        });
      }
      SolidModalAnalysis::print_table(modes, pcout);
      unsigned int n_elastic = 0, n_labelled = 0;
      double       largest_error = 0.;
      for (const auto &mode : modes)
        if (!mode.is_rigid())
          {
            ++n_elastic;
            if (mode.labelled)
              {
                ++n_labelled;
                largest_error =
                  std::max(largest_error, std::abs(mode.relative_error()));
              }
          }
      pcout << modes.size() - n_elastic << " rigid-body modes, " << n_elastic
            << " elastic modes";
      if (parameters.geometry.is_sphere())
        pcout << ", " << n_labelled
              << " labelled; largest relative error against Lamb's "
              << largest_error;
      pcout << std::endl;
      timer.print_summary();
    }

    void
    run_modal_analysis(const Parameters &parameters, MPI_Comm communicator)
    {
      if (parameters.geometry.dimension() == 3)
        return run_solid_modal_analysis(parameters, communicator);
      ConditionalOStream pcout(std::cout,
                               Utilities::MPI::this_mpi_process(communicator) ==
                                 0);
      // Rank 0's timing table, printed at the end of a run that succeeded
      // (a timer without communicator prints nothing when an error unwinds).
      TimerOutput   timer(pcout, TimerOutput::never, TimerOutput::wall_times);
      ModalAnalysis analysis(parameters.geometry,
                             parameters.material,
                             parameters.finite_element.degree,
                             parameters.modal_solver,
                             communicator,
                             timer);
      pcout << "Mesh: " << analysis.n_cells() << " cells, " << analysis.n_dofs()
            << " DoFs (Q" << parameters.finite_element.degree
            << ", boundary mapping of degree "
            << parameters.finite_element.degree << ")" << std::endl;

      const auto modes =
        analysis.run(parameters.modal_solver.n_elastic_modes());
      {
        TimerOutput::Scope scope(timer, "output");
        const std::string &directory = parameters.run.output_directory;
        analysis.write_mode_shapes(modes, directory);
        on_root(communicator, [&]() {
          ModalAnalysis::write_modes_csv(modes,
                                         directory + "/modes.csv",
                                         parameters.geometry.is_axisymmetric());
        });
      }

      ModalAnalysis::print_table(modes, pcout);
      compare_with_analytic(modes,
                            *analytic_free_modes(parameters.geometry,
                                                 parameters.material),
                            parameters.geometry.has_symmetry_boundary(),
                            parameters.run.output_directory +
                              "/analytic_modes.csv",
                            communicator,
                            pcout);
      if (parameters.modal_solver.n_torsional_modes() > 0)
        run_torsional_modes(parameters, analysis, communicator, timer, pcout);
      timer.print_summary();
    }
  } // namespace

  namespace
  {
    TaskEntry
    modal_analysis_task()
    {
      TaskEntry task;
      task.name         = "modal analysis";
      task.description  = "the lowest modes of the free body compared with "
                          "the analytic ones (modes.csv).";
      task.traits.modal = true;
      task.traits.three_dimensional = true;
      task.result_files             = {"modes.csv",
                                       "analytic_modes.csv",
                                       "modes.pvd",
                                       "modes_*.vtu",
                                       "modes_*.pvtu"};
      task.run = [](const Parameters &parameters, bool, MPI_Comm communicator) {
        run_modal_analysis(parameters, communicator);
      };
      task.build_largest_mesh =
        [](const Parameters &parameters, Triangulation<2> &, const auto &) {
          check_mode_count(parameters, "Modal analysis: 'Number of modes'");
        };
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(modal_analysis_task())
} // namespace DiskImpact
