#pragma once

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'modal analysis': the lowest modes of the free disk, labelled and
   * compared with the analytic Bessel modes. Writes modes.csv,
   * analytic_modes.csv and the mode shapes (modes.pvd), prints the table.
   */
  void
  run_modal_analysis(const Parameters &parameters, MPI_Comm communicator);
} // namespace DiskImpact
