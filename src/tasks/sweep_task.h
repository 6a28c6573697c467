#pragma once

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'sweep': one impact per velocity (and Poisson ratio) of subsection
   * Impact, with 'Error estimate' each a convergence study
   * (ImpactConvergenceStudy: epsilon extrapolated, with its error bar), to
   * restitution.csv. The points are shared out among the MPI ranks, each
   * running its own on one rank; the table is rewritten after every round
   * of one point per rank.
   */
  void
  run_sweep(const Parameters &parameters, MPI_Comm communicator);
} // namespace DiskImpact
