#pragma once

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /**
   * The checks of a run's set-up that go beyond what each subsection checks
   * of its own entries, made before anything is written: the mesh file (read
   * as the run will read it: element type, boundary, radius, domain), and
   * whether the largest mesh the task builds fits in this machine's memory
   * (the meshes are built, without finite elements, and refused as soon as
   * they outgrow it). Collective; a failure is an InputError on every rank.
   */
  void
  check_before_output(const Parameters &parameters, MPI_Comm communicator);
} // namespace DiskImpact
