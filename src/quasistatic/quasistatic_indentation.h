#pragma once

#include <mpi.h>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'quasistatic contact' for an elastic-plastic body: the half disk
   * or sphere pressed on the wall by a uniform body force
   * (WallContactProblem) is loaded to @p largest_load in @p steps equal
   * steps, unloaded in as many, and finally left at load 0, off the wall
   * (its nearest point held): the force-approach curve of loading and
   * unloading, the residual indentation, the plastic work, and the energy
   * balance of the path (the external force's work by the trapezoidal
   * rule against elastic, contact and plastic energy). Writes
   * indentation.csv (one row per step), indentation_summary.csv and the
   * states (contact.pvd with the plastic strain).
   */
  struct QuasistaticIndentation
  {
    double       largest_load   = 0.;
    unsigned int steps          = 20;
    double       tolerance      = 1e-10;
    unsigned int max_iterations = 30;

    void
    run(const Parameters &parameters, MPI_Comm communicator) const;
  };
} // namespace DiskImpact
