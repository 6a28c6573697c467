#include "tasks/sweep_task.h"

#include "base/input_error.h"
#include "base/run_error.h"
#include "impact/impact_convergence_study.h"
#include "impact/impact_estimates.h"
#include "impact/impact_mesh.h"
#include "impact/impact_simulation.h"
#include "impact/measured_contact_grading.h"
#include "output/csv_table.h"
#include "output/file_lock.h"
#include "output/hdf5_output.h"
#include "run/parameters.h"
#include "run/task_registry.h"
#include "tasks/run_checks.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The numeric columns of restitution.csv; a last column 'status' says
    /// whether the row's point is 'pending', 'done' or 'failed'.
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
                                                "one_dof_epsilon",
                                                "partner_radius",
                                                "ramirez_u",
                                                "angle",
                                                "friction",
                                                "tangential_restitution",
                                                "contact_point_restitution",
                                                "spin_final",
                                                "rebound_angle",
                                                "psi_incident",
                                                "psi_rebound",
                                                "friction_work",
                                                "plastic_work",
                                                "plastic_strain_max"};
    /// Positions of the columns that identify a point.
    constexpr unsigned int velocity_column = 0, poisson_column = 1,
                           relaxation_column = 13, partner_column = 16,
                           angle_column = 18;

    /// The entries that choose the points (and whether to resume), which a
    /// resumed sweep may change.
    const std::vector<std::pair<std::string, std::string>> point_entries{
      {"", "Output directory"},
      {"Impact", "Velocities"},
      {"Impact", "Angles of incidence"},
      {"Impact", "Poisson ratios"},
      {"Impact", "Relaxation times"},
      {"Impact", "Partner radii"},
      {"Impact", "Resume"}};

    using Row = std::vector<double>;

    /// One point of the sweep: its parameters and its row.
    struct Point
    {
      Parameters  parameters;
      Row         row;
      std::string status = "pending";
    };

    /// The sweep's points in the order of the table: Poisson ratios, then
    /// relaxation times, then partner radii, then angles, then velocities
    /// (empty lists: the material's, the partner's, 'Angle of incidence').
    std::vector<Point>
    sweep_points(const Parameters &parameters)
    {
      auto or_material = [](std::vector<double> values) {
        if (values.empty())
          values.push_back(std::nan(""));
        return values;
      };
      std::vector<Point> points;
      for (const double nu : or_material(parameters.impact.poisson_ratios()))
        for (const double tau :
             or_material(parameters.impact.relaxation_times()))
          for (const double r2 : or_material(parameters.impact.partner_radii()))
            for (const double angle :
                 or_material(parameters.impact.incidence_angles()))
            for (const double v : parameters.impact.velocities())
              {
                Point point{parameters, Row(column_names.size(), std::nan(""))};
                auto &material = point.parameters.material;
                auto &partner  = point.parameters.partner;
                if (!std::isnan(nu))
                  material = material.with_poisson_ratio(nu);
                if (!std::isnan(tau))
                  material = material.with_relaxation_time(tau);
                if (!std::isnan(r2))
                  partner = partner.with_radius(r2);
                point.parameters.impact.set_velocity(v);
                if (!std::isnan(angle))
                  point.parameters.impact.set_incidence_angle_degrees(angle);
                point.row[velocity_column] = v;
                point.row[angle_column] =
                  point.parameters.impact.incidence_angle_degrees();
                point.row[angle_column + 1] =
                  parameters.contact.friction_coefficient();
                point.row[poisson_column]  = material.poisson_ratio();
                point.row[8]               = material.in_plane_poisson_ratio();
                point.row[relaxation_column] = material.relaxation_time();
                if (partner.is_body())
                  point.row[partner_column] = partner.radius();
                points.push_back(std::move(point));
              }
      return points;
    }

    /// Whether two rows are of the same point (the table keeps 15 digits).
    bool
    same_point(const Row &a, const Row &b)
    {
      for (const unsigned int c : {velocity_column,
                                   poisson_column,
                                   relaxation_column,
                                   partner_column,
                                   angle_column})
        if (std::abs(a[c] - b[c]) > 1e-12 * std::max(1., std::abs(b[c])))
          return false;
      return true;
    }

    /// Run one point on this rank alone: its row of restitution.csv, epsilon
    /// and its error from the convergence study if 'Convergence study per
    /// point' is set.
    Row
    run_point(const Point &point)
    {
      const Parameters &parameters = point.parameters;
      const auto        start      = std::chrono::steady_clock::now();
      ConvergedEpsilon  result;
      if (parameters.impact.estimate_errors())
        result = ImpactConvergenceStudy(parameters.impact_convergence)
                   .run(parameters, MPI_COMM_SELF, nullptr);
      else
        {
          result.base =
            run_impact(with_mesh_graded_for_measured_contact(parameters,
                                                             MPI_COMM_SELF),
                       MPI_COMM_SELF,
                       false);
          result.epsilon = result.base.epsilon;
          result.error   = std::nan("");
        }
      const double wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      const ImpactSummary &s = result.base;
      Row                  row{point.row};
      for (const auto &[column, value] :
           std::vector<std::pair<unsigned int, double>>{
             {2, result.epsilon},
             {3, result.error},
             {4, s.contact_time},
             {5, s.delta_max},
             {6, s.force_max},
             {7, s.energy_error},
             {9, s.epsilon},
             {10, static_cast<double>(s.steps)},
             {11, static_cast<double>(s.n_dofs)},
             {12, wall_time},
             {14, s.schwager_alpha},
             {15, s.one_dof_epsilon},
             {17, s.ramirez_u},
             {20, s.oblique.tangential_restitution()},
             {21, s.oblique.contact_point_restitution()},
             {22, s.oblique.spin_final},
             {23, s.oblique.rebound_angle},
             {24, s.oblique.psi_incident},
             {25, s.oblique.psi_rebound},
             {26, s.oblique.friction_work},
             {27, s.plastic_work},
             {28, s.plastic_strain_max}})
        row[column] = value;
      return row;
    }

    /// The header of the terminal table: speeds and contact times in the
    /// units of the parameter file (m/s and s with 'Units = SI').
    std::string
    table_header(const UnitSystem &units)
    {
      return units.is_si() ?
               "   v [m/s]   v/c     nu    nu2       epsilon     error   "
               "contact time [s]  alpha/u_R  energy err.   time\n" :
               "   v/c      nu    nu2       epsilon     error      "
               "contact time  alpha/u_R  energy err.   time\n";
    }

    /// A point's row as a line of the terminal table (table_header()).
    std::string
    describe(const Row &row, const UnitSystem &units)
    {
      std::ostringstream line;
      // Schwager's alpha for a disk, Ramírez et al.'s u for a sphere.
      const double dissipation = std::isnan(row[14]) ? row[17] : row[14];
      if (units.is_si())
        line << std::setprecision(4) << std::setw(10) << row[0] * units.speed();
      line << std::fixed << std::setprecision(4) << std::setw(7) << row[0]
           << std::setw(8) << row[1] << std::setw(7) << row[8]
           << std::setprecision(7) << std::setw(12) << row[2] << std::scientific
           << std::setprecision(1) << std::setw(10) << row[3];
      if (units.is_si())
        line << std::setprecision(4) << std::setw(17) << row[4] * units.time()
             << std::fixed;
      else
        line << std::fixed << std::setprecision(4) << std::setw(12) << row[4];
      line << std::fixed << std::setprecision(4) << std::setw(11) << dissipation
           << std::scientific << std::setprecision(1) << std::setw(11) << row[7]
           << std::fixed << std::setw(8) << row[12] << " s";
      if (!std::isnan(row[partner_column]))
        line << std::setprecision(4) << "  R2 = " << row[partner_column];
      // An oblique impact: its angle, e_t, the contact point's restitution
      // and the spin after.
      if (row[angle_column] != 0.)
        line << std::setprecision(4) << "  angle " << row[angle_column]
             << " e_t " << row[20] << " beta " << row[21] << " spin "
             << std::setprecision(6) << row[22];
      return line.str();
    }

    /**
     * restitution.csv and restitution.h5: one row per point with its
     * status. Each rank that finishes a point writes both, one rank at a
     * time (a lock file), from the rows on disk and its own.
     */
    class SweepTable
    {
    public:
      SweepTable(const std::string &directory,
                 std::vector<Point> points,
                 const std::string &parameters_json,
                 const std::string &units,
                 const UnitSystem  &unit_system)
          : csv_file(directory + "/restitution.csv")
          , h5_file(directory + "/restitution.h5")
          , lock_file(directory + "/.restitution.lock")
          , points(std::move(points))
          , parameters_json(parameters_json)
          , units(units)
          , unit_system(unit_system)
      {
      }

      /// Take the finished rows (with @p failed_too also the failed ones)
      /// of the table on disk whose points are ours.
      void
      keep_finished_rows(const bool failed_too = false)
      {
        if (!std::filesystem::exists(csv_file))
          return;
        const CsvTable old = CsvTable::read(csv_file);
        check_columns(old);
        const auto                       status = old.text_column("status");
        std::vector<std::vector<double>> columns;
        for (const auto &name : column_names)
          columns.push_back(old.column(name));
        for (unsigned int r = 0; r < old.n_rows(); ++r)
          {
            if (status[r] != "done" && !(failed_too && status[r] == "failed"))
              continue;
            Row row;
            for (const auto &column : columns)
              row.push_back(column[r]);
            for (auto &point : points)
              if (same_point(point.row, row))
                {
                  point.row    = row;
                  point.status = status[r];
                }
          }
      }

      /// Record @p row (status @p status) of point @p index and write the
      /// table with the other ranks' rows as they are on disk; returns the
      /// number of points done.
      unsigned int
      record(const unsigned int index,
             const Row         &row,
             const std::string &status)
      {
        const FileLock lock(lock_file);
        keep_finished_rows(true);
        points[index].row    = row;
        points[index].status = status;
        write();
        return n_done();
      }

      /// Write both files as the rows are now.
      void
      write() const
      {
        CsvTable table(column_names);
        CsvTable with_status([]() {
          auto names = column_names;
          names.push_back("status");
          return names;
        }());
        for (const auto &point : points)
          {
            table.start_row();
            with_status.start_row();
            for (const double value : point.row)
              {
                table.add(value);
                with_status.add(value);
              }
            with_status.add(point.status);
          }
        with_status.write(csv_file);
        Hdf5Output h5(h5_file);
        h5.write_table("restitution", table);
        std::vector<double> done;
        for (const auto &point : points)
          done.push_back(point.status == "done" ? 1. : 0.);
        h5.write_vector("restitution", "done", done);
        h5.set_attribute("restitution", "points_done", 1. * n_done());
        h5.set_attribute("restitution", "points_total", 1. * points.size());
        h5.set_attribute("restitution",
                         "complete",
                         n_done() == points.size() ? 1. : 0.);
        h5.set_attribute("/",
                         "units",
                         units +
                           "; relaxation_time in the parameter file's time "
                           "unit, wall_time in s; the rest dimensionless");
        h5.set_attribute("/", "parameters", parameters_json);
        h5.set_si_unit_attributes(unit_system);
        h5.finish();
      }

      unsigned int
      n_done() const
      {
        return std::count_if(points.begin(), points.end(), [](const Point &p) {
          return p.status == "done";
        });
      }

      const std::vector<Point> &
      get_points() const
      {
        return points;
      }

    private:
      void
      check_columns(const CsvTable &table) const
      {
        auto expected = column_names;
        expected.push_back("status");
        if (table.column_names() != expected)
          throw std::runtime_error(csv_file +
                                   " has other columns than a sweep writes: "
                                   "set 'Resume = false' to start afresh");
      }

      const std::string  csv_file, h5_file, lock_file;
      std::vector<Point> points;
      const std::string  parameters_json;
      /// The HDF5 root attribute 'units'.
      const std::string units;
      /// The run's units (SI scales as root attributes).
      const UnitSystem unit_system;
    };

    /// The index of the next pending point to run, shared by all ranks: an
    /// integer on rank 0, fetched and incremented atomically (MPI
    /// one-sided).
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

    /// A parameter file's parameters as text, the point entries blanked.
    std::string
    without_point_entries(const std::string &prm_text)
    {
      ParameterHandler prm;
      Parameters::declare_parameters(prm);
      prm.parse_input_from_string(prm_text);
      for (const auto &[subsection, entry] : point_entries)
        {
          if (!subsection.empty())
            prm.enter_subsection(subsection);
          prm.set(entry, entry == "Resume" ? "true" : "");
          if (!subsection.empty())
            prm.leave_subsection();
        }
      std::ostringstream text;
      prm.print_parameters(text,
                           ParameterHandler::OutputStyle(
                             ParameterHandler::ShortPRM |
                             ParameterHandler::KeepDeclarationOrder));
      return text.str();
    }

    /// The first entry in which two parameter texts differ, as
    /// "Subsection: entry = A there, B here"; empty if none does.
    std::string
    first_difference(const std::string &there, const std::string &here)
    {
      std::istringstream a(there), b(here);
      std::string        line_a, line_b, subsection;
      while (std::getline(a, line_a) && std::getline(b, line_b))
        {
          const auto first = line_a.find_first_not_of(' ');
          if (first != std::string::npos &&
              line_a.compare(first, 11, "subsection ") == 0)
            subsection = line_a.substr(first + 11);
          if (line_a != line_b)
            {
              auto value = [](const std::string &line) {
                const auto eq = line.find('=');
                return eq == std::string::npos ? line : line.substr(eq + 2);
              };
              const auto eq   = line_a.find('=');
              const auto name = line_a.substr(line_a.find("set ") + 4,
                                              eq == std::string::npos ?
                                                0 :
                                                eq - line_a.find("set ") - 5);
              return (subsection.empty() ? "" : subsection + ": ") + name +
                     " = " + value(line_a) + " there, " + value(line_b) +
                     " here";
            }
        }
      return "";
    }
  } // namespace

  std::vector<std::string>
  sweep_result_files()
  {
    return {"restitution.csv", "restitution.h5"};
  }

  bool
  sweep_resumes(const Parameters       &parameters,
                const ParameterHandler &prm,
                MPI_Comm                communicator)
  {
    const std::string &directory = parameters.run.output_directory;
    bool               resumes   = false;
    collectively(communicator, [&]() {
      if (!parameters.impact.resume() ||
          !std::filesystem::exists(directory + "/restitution.csv"))
        return;
      const auto refuse = [&](const std::string &why) {
        throw InputError("output directory '" + directory +
                         "' holds a sweep of other parameters (" + why +
                         "); set 'Resume = false' in subsection Impact to "
                         "start afresh, or choose another 'Output "
                         "directory'");
      };
      std::ifstream     old_file(directory + "/used_parameters.prm");
      std::stringstream old_text;
      old_text << old_file.rdbuf();
      std::ostringstream new_text;
      prm.print_parameters(new_text, ParameterHandler::ShortPRM);
      std::string there;
      try
        {
          there = without_point_entries(old_text.str());
        }
      catch (const std::exception &)
        {
          refuse("its used_parameters.prm is missing or unreadable");
        }
      const std::string difference =
        first_difference(there, without_point_entries(new_text.str()));
      if (!difference.empty())
        refuse(difference);
      resumes = true;
    });
    return resumes;
  }

  void
  run_sweep(const Parameters &parameters,
            const bool        resume,
            MPI_Comm          communicator)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    SweepTable         table(parameters.run.output_directory,
                     sweep_points(parameters),
                     parameters.run.parameters_json,
                     output_units(parameters),
                     parameters.units);
    // Every rank reads the kept rows: all must agree on the pending points.
    collectively(communicator, [&]() {
      if (resume)
        table.keep_finished_rows();
    });
    on_root(communicator, [&]() { table.write(); });
    const auto &points = table.get_points();
    // The fastest points first: their studies tend to take the most levels,
    // so the long points start first and the short ones fill the ranks'
    // ends (on the twenty-speed plane-stress curve the two fastest points
    // take two thirds of the work; docs/guide/sweeps.md, "On several MPI
    // ranks"). Every rank sorts alike.
    std::vector<int> pending;
    for (unsigned int i = 0; i < points.size(); ++i)
      if (points[i].status != "done")
        pending.push_back(i);
    std::stable_sort(pending.begin(), pending.end(), [&](int a, int b) {
      return points[a].row[velocity_column] > points[b].row[velocity_column];
    });
    const unsigned int n_total = points.size();
    const unsigned int n_kept  = n_total - pending.size();
    if (rank == 0)
      std::cout << "Sweep of " << n_total << " points"
                << (n_kept > 0 ? ", " + std::to_string(n_kept) +
                                   " kept from the earlier run" :
                                 "")
                << "\n"
                << table_header(parameters.units) << std::flush;

    // Each rank takes the next pending point when it is free (a counter on
    // rank 0, MPI one-sided) and records its row itself.
    NextPointCounter counter(communicator);
    const auto       start = std::chrono::steady_clock::now();
    std::string      failure;
    unsigned int     n_failed = 0;
    for (int next = counter.next(); next < static_cast<int>(pending.size());
         next     = counter.next())
      {
            const unsigned int index = pending[next];
            Row                row   = points[index].row;
            std::string        note;
            try
          {
                row = run_point(points[index]);
          }
            catch (const std::exception &e)
          {
                note = std::string(" failed: ") + e.what();
                if (n_failed++ == 0)
              failure = "v/c = " + Utilities::to_string(row[0]) +
                        ", nu = " + Utilities::to_string(row[1]) +
                        ", tau = " + Utilities::to_string(row[13]) + ": " +
                        e.what();
          }
            unsigned int n_done = 0;
            try
          {
                n_done = table.record(index, row, note.empty() ? "done" : "failed");
          }
            catch (const std::exception &e)
          {
                // The table cannot be written: take no more points.
            failure = e.what();
            ++n_failed;
            break;
          }
        // Progress: one line, written at once, whichever rank prints it.
        const double elapsed = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                     .count();
            std::ostringstream line;
            line << describe(row, parameters.units) << note << "  [" << n_done
                 << "/" << n_total;
            if (n_done > n_kept && n_done < n_total)
          line << ", about "
               << std::lround(elapsed / (n_done - n_kept) * (n_total - n_done))
               << " s left";
        line << "]\n";
            std::cout << line.str() << std::flush;
      }

    // Every rank is done: a failure of any rank ends the run with an error.
    const unsigned int total_failed =
      Utilities::MPI::sum(n_failed, communicator);
    std::string first;
    for (const auto &f : Utilities::MPI::all_gather(communicator, failure))
      if (first.empty())
        first = f;
    if (total_failed > 0)
      throw RunError("sweep incomplete, " + std::to_string(total_failed) +
                     " point(s) failed (first: " + first +
                     "); the finished points are kept in restitution.csv: "
                     "rerun to compute the rest");
  }

  void
  check_sweep(const Parameters &parameters)
  {
    const auto          &impact = parameters.impact;
    std::vector<Partner> partners{parameters.partner};
    if (!impact.partner_radii().empty())
      partners.clear();
    for (const double r2 : impact.partner_radii())
      partners.push_back(parameters.partner.with_radius(r2));
    std::vector<double> angles = impact.incidence_angles();
    if (angles.empty())
      angles.push_back(impact.incidence_angle_degrees());
    for (const Partner &other : partners)
      for (const double angle : angles)
        for (const double v : impact.velocities())
          {
            Parameters point = parameters;
            point.partner    = other;
            point.impact.set_velocity(v);
            point.impact.set_incidence_angle_degrees(angle);
            check_impact_time_step(point);
          }
    require(!impact.velocities().empty(),
            "Impact: 'Velocities' is empty: task 'sweep' needs at least "
            "one impact speed");
    // Every point's material, checked before any point runs.
    const auto in_list = [](const std::string &entry, const auto &check) {
      try
        {
          check();
        }
      catch (const InputError &e)
        {
          throw InputError("Impact: an entry of '" + entry +
                           "' is out of range (" + e.what() + ")");
        }
    };
    for (const double nu : impact.poisson_ratios())
      in_list("Poisson ratios",
              [&]() { parameters.material.with_poisson_ratio(nu); });
    for (const double tau : impact.relaxation_times())
      in_list("Relaxation times",
              [&]() { parameters.material.with_relaxation_time(tau); });
  }

  template <int dim>
  void
  build_fastest_mesh(const Parameters                          &parameters,
                     Triangulation<dim>                        &mesh,
                     const std::function<double(unsigned int)> &cell_budget)
  {
    in_context("Sweep: the fastest impact's finest mesh", [&]() {
      Parameters fastest =
        parameters.impact.estimate_errors() ?
          ImpactConvergenceStudy(parameters.impact_convergence)
            .finest(parameters) :
          parameters;
      const auto &velocities = parameters.impact.velocities();
      fastest.impact.set_velocity(
        *std::max_element(velocities.begin(), velocities.end()));
      // The largest normal speed: the smallest angle.
      const auto &angles = parameters.impact.incidence_angles();
      if (!angles.empty())
        fastest.impact.set_incidence_angle_degrees(
          *std::min_element(angles.begin(), angles.end()));
      create_impact_mesh(fastest,
                         mesh,
                         cell_budget(fastest.finite_element.degree));
    });
  }

  template void
  build_fastest_mesh(const Parameters &,
                     Triangulation<2> &,
                     const std::function<double(unsigned int)> &);
  template void
  build_fastest_mesh(const Parameters &,
                     Triangulation<3> &,
                     const std::function<double(unsigned int)> &);

  namespace
  {
    TaskEntry
    sweep_task()
    {
      TaskEntry task;
      task.name        = "sweep";
      task.description = "epsilon(v) for the velocities of subsection Impact, "
                         "and for its angles of incidence the tangential "
                         "restitution and spin (restitution.csv).";
      task.traits.impacts           = true;
      task.traits.sweeps            = true;
      task.traits.partner_body      = true;
      task.traits.one_mesh_per_rank = true;
      task.traits.three_dimensional = true;
      task.traits.plasticity        = true;
      task.result_files             = sweep_result_files();
      task.run                      = run_sweep;
      task.check                    = check_sweep;
      task.build_largest_mesh       = build_fastest_mesh<2>;
      task.build_largest_solid_mesh = build_fastest_mesh<3>;
      return task;
    }
  } // namespace

  DISKIMPACT_REGISTER_TASK(sweep_task())
} // namespace DiskImpact
