#pragma once

#include <mpi.h>

#include <functional>
#include <string>

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

  /// Rethrow an InputError of @p check with @p context in front.
  void
  in_context(const std::string &context, const std::function<void()> &check);

  /// An InputError unless the modes a modal analysis of @p parameters asks
  /// for ('Number of modes', named @p entry in the message) are at most
  /// half its DoFs.
  void
  check_mode_count(const Parameters &parameters, const std::string &entry);
} // namespace DiskImpact
