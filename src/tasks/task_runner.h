#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Run the task named in @p parameters: create the output directory, store
   * the parameters used in it, print the run's set-up and dispatch.
   */
  void
  run_task(const Parameters               &parameters,
           const dealii::ParameterHandler &prm,
           MPI_Comm                        communicator);
} // namespace DiskImpact
