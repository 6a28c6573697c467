#include "base/peak_memory.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

namespace DiskImpact
{
  double
  peak_memory_mb(MPI_Comm communicator)
  {
    dealii::Utilities::System::MemoryStats memory;
    dealii::Utilities::System::get_memory_stats(memory);
    // VmHWM is in kB.
    return dealii::Utilities::MPI::sum(static_cast<double>(memory.VmHWM),
                                       communicator) /
           1024.;
  }
} // namespace DiskImpact
