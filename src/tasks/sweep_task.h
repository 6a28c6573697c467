#pragma once

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'sweep': one impact per velocity (and Poisson ratio) of subsection
   * Impact, each with an error estimate from a refined run (mesh, contact
   * elements, time step and penalty), to restitution.csv, rewritten after
   * every point.
   */
  void
  run_sweep(const Parameters &parameters, MPI_Comm communicator);
} // namespace DiskImpact
