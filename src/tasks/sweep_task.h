#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /// The result files of task 'sweep' (restitution.csv and .h5).
  std::vector<std::string>
  sweep_result_files();

  /**
   * Whether a sweep continues an earlier one in its output directory: with
   * 'Resume' set and a table of finished points there. Throws an InputError
   * if that table came from other parameters (everything but the lists of
   * points, 'Resume' and the output directory counts). Collective.
   */
  bool
  sweep_resumes(const Parameters               &parameters,
                const dealii::ParameterHandler &prm,
                MPI_Comm                        communicator);

  /**
   * Task 'sweep': one impact per point (velocity, Poisson ratio, relaxation
   * time of subsection Impact), with 'Convergence study per point' each a
   * convergence study (ImpactConvergenceStudy: epsilon extrapolated, with its
   * error bar). The points are shared out among the MPI ranks, each taking the
   * next point when it is free and running it alone.
   *
   * restitution.csv has one row per point from the start, its 'status'
   * 'pending', 'done' or 'failed'; restitution.h5 the same columns and the
   * attributes 'complete', 'points_done' and 'points_total'. A rank that
   * finishes a point writes both files at once (one rank at a time, under
   * a file lock), and prints the row with the progress. With @p resume the
   * finished rows of the earlier run are kept and only the others run. A
   * point that fails is marked 'failed' and the others go on; the run then
   * ends with an error naming it.
   */
  void
  run_sweep(const Parameters &parameters, bool resume, MPI_Comm communicator);

  /// The checks of a sweep's points before any runs: every point's time
  /// step and material.
  void
  check_sweep(const Parameters &parameters);

  /// The fastest impact's finest mesh (it needs the largest contact zone),
  /// within @p cell_budget(degree) cells.
  template <int dim>
  void
  build_fastest_mesh(const Parameters                          &parameters,
                     dealii::Triangulation<dim>                &mesh,
                     const std::function<double(unsigned int)> &cell_budget);
} // namespace DiskImpact
