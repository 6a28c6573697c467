#pragma once

#include <mpi.h>

namespace DiskImpact
{
  /// The largest resident memory (VmHWM) of the processes of
  /// @p communicator so far, summed over them [MB]. Collective.
  double
  peak_memory_mb(MPI_Comm communicator);
} // namespace DiskImpact
