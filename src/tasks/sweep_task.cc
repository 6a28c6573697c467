#include "tasks/sweep_task.h"

#include "base/parameters.h"
#include "output/csv_table.h"
#include "output/hdf5_output.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
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
                                                "wall_time",
                                                "relaxation_time",
                                                "alpha",
                                                "one_dof_epsilon"};

    using Row = std::vector<double>;

    /// One point of the sweep: Poisson ratio and relaxation time (NaN: the
    /// material's), velocity.
    struct Point
    {
      double nu;
      double tau;
      double v;
    };

    /// One point of the sweep on this rank alone: the row of
    /// restitution.csv, epsilon and its error from the convergence study
    /// if 'Error estimate' is set.
    Row
    run_point(const Parameters &parameters, const Point &where)
    {
      Parameters point = parameters;
      if (!std::isnan(where.nu))
        point.material = point.material.with_poisson_ratio(where.nu);
      if (!std::isnan(where.tau))
        point.material = point.material.with_relaxation_time(where.tau);
      point.impact.set_velocity(where.v);
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
      return {where.v,
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
              wall_time,
              point.material.relaxation_time(),
              s.schwager_alpha,
              s.one_dof_epsilon};
    }

    std::string
    describe(const std::vector<double> &row)
    {
      std::ostringstream line;
      line << std::fixed << std::setprecision(4) << std::setw(7) << row[0]
           << std::setw(8) << row[1] << std::setw(7) << row[8]
           << std::setprecision(7) << std::setw(12) << row[2] << std::scientific
           << std::setprecision(1) << std::setw(10) << row[3] << std::fixed
           << std::setprecision(4) << std::setw(12) << row[4] << std::setw(7)
           << row[14] << std::scientific << std::setprecision(1)
           << std::setw(11) << row[7] << std::fixed << std::setw(8) << row[12]
           << " s\n";
      return line.str();
    }

    /// The index of the next point to run, shared by all ranks: an integer
    /// on rank 0, fetched and incremented atomically (MPI one-sided).
    class NextPointCounter
    {
    public:
      explicit NextPointCounter(MPI_Comm communicator)
      {
        const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
        MPI_Win_allocate(root ? sizeof(int) : 0,
                         sizeof(int),
                         MPI_INFO_NULL,
                         communicator,
                         &value,
                         &window);
        if (root)
          *value = 0;
        MPI_Barrier(communicator);
      }
      ~NextPointCounter()
      {
        MPI_Win_free(&window);
      }
      int
      next()
      {
        const int one = 1;
        int       index;
        MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window);
        MPI_Fetch_and_op(&one, &index, MPI_INT, 0, 0, MPI_SUM, window);
        MPI_Win_unlock(0, window);
        return index;
      }

    private:
      int    *value = nullptr;
      MPI_Win window;
    };

    /// Rows sent by the other ranks (tag = point index); @p wait: block
    /// for at least one.
    void
    receive_rows(MPI_Comm            communicator,
                 const bool          wait,
                 std::map<int, Row> &rows)
    {
      int        arrived = wait ? 1 : 0;
      MPI_Status status;
      if (!wait)
        MPI_Iprobe(
          MPI_ANY_SOURCE, MPI_ANY_TAG, communicator, &arrived, &status);
      while (arrived)
        {
          Row row(column_names.size());
          MPI_Recv(row.data(),
                   row.size(),
                   MPI_DOUBLE,
                   MPI_ANY_SOURCE,
                   MPI_ANY_TAG,
                   communicator,
                   &status);
          rows[status.MPI_TAG] = row;
          MPI_Iprobe(
            MPI_ANY_SOURCE, MPI_ANY_TAG, communicator, &arrived, &status);
        }
    }

    /// restitution.csv and restitution.h5 (@p filename without suffix) with
    /// the rows done so far, in the order of the points; print the rows not
    /// in @p printed yet.
    void
    write_rows(const std::map<int, Row> &rows,
               const std::string        &filename,
               std::set<int>            &printed,
               ConditionalOStream       &out)
    {
      CsvTable table(column_names);
      for (const auto &[index, row] : rows)
        {
          table.start_row();
          for (const double value : row)
            table.add(value);
          if (printed.insert(index).second)
            out << describe(row) << std::flush;
        }
      table.write(filename + ".csv");
      Hdf5Output h5(filename + ".h5");
      h5.write_table("restitution", table);
      h5.finish();
    }
  } // namespace

  void
  run_sweep(const Parameters &parameters, MPI_Comm communicator)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    ConditionalOStream pcout(std::cout, rank == 0);

    // Empty lists: the material's value (NaN).
    auto or_material = [](std::vector<double> values) {
      if (values.empty())
        values.push_back(std::nan(""));
      return values;
    };
    std::vector<Point> points;
    for (const double nu : or_material(parameters.impact.poisson_ratios()))
      for (const double tau : or_material(parameters.impact.relaxation_times()))
        for (const double v : parameters.impact.velocities())
          points.push_back({nu, tau, v});

    pcout << "   v/c      nu    nu2       epsilon     error      contact "
             "time  alpha  energy err.   time\n";
    // Each rank takes the next point when it is free (a counter on rank 0,
    // MPI one-sided), sends its row to rank 0, which rewrites
    // restitution.csv whenever it has new rows.
    NextPointCounter   counter(communicator);
    std::map<int, Row> rows;
    std::set<int>      printed;
    const int          n_points = points.size();
    const std::string  filename =
      parameters.run.output_directory + "/restitution";
    for (int i = counter.next(); i < n_points; i = counter.next())
      {
        Row row = run_point(parameters, points[i]);
        if (rank == 0)
          {
            rows[i] = row;
            receive_rows(communicator, false, rows);
            write_rows(rows, filename, printed, pcout);
          }
        else
          MPI_Send(row.data(), row.size(), MPI_DOUBLE, 0, i, communicator);
      }
    if (rank == 0)
      while (static_cast<int>(rows.size()) < n_points)
        {
          receive_rows(communicator, true, rows);
          write_rows(rows, filename, printed, pcout);
        }
  }
} // namespace DiskImpact
