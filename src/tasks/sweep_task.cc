#include "tasks/sweep_task.h"

#include "csv_table.h"
#include "parameters.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    const std::vector<std::string> column_names{"velocity",
                                                "poisson_ratio",
                                                "epsilon",
                                                "epsilon_error",
                                                "contact_time",
                                                "delta_max",
                                                "force_max",
                                                "energy_error",
                                                "poisson_ratio_2d",
                                                "epsilon_base",
                                                "steps",
                                                "n_dofs",
                                                "wall_time"};

    /// One point of the sweep on this rank alone: the row of
    /// restitution.csv, epsilon and its error from the convergence study
    /// if 'Error estimate' is set.
    std::vector<double>
    run_point(const Parameters &parameters, const double nu, const double v)
    {
      Parameters point = parameters;
      if (!std::isnan(nu))
        point.material = parameters.material.with_poisson_ratio(nu);
      point.impact.set_velocity(v);
      const auto       start = std::chrono::steady_clock::now();
      ConvergedEpsilon result;
      if (parameters.impact.estimate_errors())
        result = point.impact_convergence.run(point, MPI_COMM_SELF, nullptr);
      else
        {
          result.base    = point.impact.run(point, MPI_COMM_SELF, false);
          result.epsilon = result.base.epsilon;
          result.error   = std::nan("");
        }
      const double wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      const ImpactSummary &s = result.base;
      return {v,
              point.material.poisson_ratio(),
              result.epsilon,
              result.error,
              s.contact_time,
              s.delta_max,
              s.force_max,
              s.energy_error,
              point.material.in_plane_poisson_ratio(),
              s.epsilon,
              static_cast<double>(s.steps),
              static_cast<double>(s.n_dofs),
              wall_time};
    }

    std::string
    describe(const std::vector<double> &row)
    {
      std::ostringstream line;
      line << std::fixed << std::setprecision(4) << std::setw(7) << row[0]
           << std::setw(8) << row[1] << std::setw(7) << row[8]
           << std::setprecision(7) << std::setw(12) << row[2] << std::scientific
           << std::setprecision(1) << std::setw(10) << row[3] << std::fixed
           << std::setprecision(4) << std::setw(12) << row[4] << std::scientific
           << std::setprecision(1) << std::setw(11) << row[7] << std::fixed
           << std::setw(8) << row[12] << " s\n";
      return line.str();
    }
  } // namespace

  void
  run_sweep(const Parameters &parameters, MPI_Comm communicator)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    ConditionalOStream pcout(std::cout, rank == 0);

    std::vector<std::pair<double, double>> points;
    std::vector<double> ratios = parameters.impact.poisson_ratios();
    if (ratios.empty())
      ratios.push_back(std::nan(""));
    for (const double nu : ratios)
      for (const double v : parameters.impact.velocities())
        points.emplace_back(nu, v);

    CsvTable table(column_names);
    pcout << "   v/c      nu    nu2       epsilon     error      contact "
             "time  energy err.   time\n";
    // Rounds of one point per rank; after each, rank 0 gathers the rows
    // and rewrites restitution.csv.
    const std::size_t n_columns = column_names.size();
    for (std::size_t first = 0; first < points.size(); first += n_ranks)
      {
        std::vector<double> row(n_columns, std::nan(""));
        if (first + rank < points.size())
          row = run_point(parameters,
                          points[first + rank].first,
                          points[first + rank].second);
        const auto rows = Utilities::MPI::gather(communicator, row, 0);
        if (rank != 0)
          continue;
        for (std::size_t r = 0; r < n_ranks && first + r < points.size(); ++r)
          {
            table.start_row();
            for (std::size_t c = 0; c < n_columns; ++c)
              table.add(rows[r][c]);
            pcout << describe(rows[r]) << std::flush;
          }
        table.write(parameters.run.output_directory + "/restitution.csv");
      }
  }
} // namespace DiskImpact
