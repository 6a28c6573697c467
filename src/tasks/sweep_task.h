#pragma once

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'sweep': one impact per velocity (and Poisson ratio) of subsection
   * Impact, with 'Error estimate' each a convergence study
   * (ImpactConvergenceStudy: epsilon extrapolated, with its error bar), to
   * restitution.csv and restitution.h5. The points are shared out among
   * the MPI ranks, each taking the next point when it is free and running
   * it alone; rank 0 rewrites the table whenever it has new rows.
   */
  void
  run_sweep(const Parameters &parameters, MPI_Comm communicator);
} // namespace DiskImpact
