#include "tasks/modal_analysis_task.h"

#include "base/parameters.h"
#include "base/run_error.h"
#include "modal/modal_analysis.h"
#include "modal/torsional_modal_analysis.h"
#include "output/csv_table.h"
#include "reference/sphere_torsional_modes.h"

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

    /// A sphere's torsional modes: torsional_modes.csv and their table,
    /// with the labels checked against Lamb's ordering.
    void
    run_torsional_modes(const Parameters   &parameters,
                        MPI_Comm            communicator,
                        TimerOutput        &timer,
                        ConditionalOStream &pcout)
    {
      const unsigned int n_wanted = parameters.modal_solver.n_torsional_modes();
      TorsionalModalAnalysis torsion(parameters.geometry,
                                     parameters.material,
                                     parameters.finite_element.degree,
                                     parameters.modal_solver,
                                     communicator,
                                     timer);
      const auto             modes = torsion.run(n_wanted);
      on_root(communicator, [&]() {
        ModalAnalysis::write_modes_csv(modes,
                                       parameters.run.output_directory +
                                         "/torsional_modes.csv",
                                       true);
      });
      pcout << "Torsional modes (u_phi only):\n";
      ModalAnalysis::print_table(modes, pcout);
      const Reference::SphereTorsionalModes reference(
        parameters.material.transverse_wave_speed(),
        parameters.geometry.radius());
      const auto analytic = reference.lowest_modes(n_wanted);
      on_root(communicator, [&]() {
        write_analytic_modes(reference,
                             analytic,
                             parameters.run.output_directory +
                               "/torsional_analytic_modes.csv");
      });
      // The computed labels in order, as long as they equal Lamb's.
      unsigned int n_matching = 0, matched_so_far = 0;
      double       max_error = 0.;
      for (const auto &mode : modes)
        if (!mode.is_rigid())
          {
            max_error = std::max(max_error, std::abs(mode.relative_error()));
            if (n_matching == matched_so_far && n_matching < analytic.size() &&
                mode.label == analytic[n_matching])
              ++n_matching;
            ++matched_so_far;
          }
      pcout << n_wanted << " torsional modes, largest relative error "
            << max_error << "\nLabels equal to the analytic ordering: first "
            << n_matching << " of " << analytic.size() << std::endl;
    }
  } // namespace

  void
  run_modal_analysis(const Parameters &parameters, MPI_Comm communicator)
  {
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
          << ", boundary mapping of degree " << parameters.finite_element.degree
          << ")" << std::endl;

    const auto modes = analysis.run(parameters.modal_solver.n_elastic_modes());
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

    unsigned int n_rigid   = 0;
    double       max_error = 0.;
    for (const auto &mode : modes)
      if (mode.is_rigid())
        ++n_rigid;
      else
        max_error = std::max(max_error, std::abs(mode.relative_error()));
    ModalAnalysis::print_table(modes, pcout);

    // The analytic modes in their own order, beside the computed labels.
    const auto reference =
      analytic_free_modes(parameters.geometry, parameters.material);
    const auto analytic =
      reference->lowest_modes(modes.size() - n_rigid,
                              parameters.geometry.is_half_disk());
    unsigned int n_matching = 0;
    while (n_matching < analytic.size() &&
           modes[n_rigid + n_matching].label == analytic[n_matching])
      ++n_matching;
    on_root(communicator, [&]() {
      write_analytic_modes(*reference,
                           analytic,
                           parameters.run.output_directory +
                             "/analytic_modes.csv");
    });
    pcout << n_rigid << " rigid-body modes, " << modes.size() - n_rigid
          << " elastic modes, largest relative error " << max_error
          << "\nLabels equal to the analytic ordering: first " << n_matching
          << " of " << analytic.size() << " elastic modes" << std::endl;
    if (parameters.modal_solver.n_torsional_modes() > 0)
      run_torsional_modes(parameters, communicator, timer, pcout);
    timer.print_summary();
  }
} // namespace DiskImpact
