#pragma once

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /// Task 'impact': one impact, its time series, summary and a printout.
  void
  run_impact(const Parameters &parameters, MPI_Comm communicator);
} // namespace DiskImpact
