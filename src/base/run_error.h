#pragma once

#include "base/input_error.h"

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace DiskImpact
{
  /**
   * A failure during a run (a time step that cannot converge, a result that
   * fails a physical check, a file that cannot be written) that every MPI
   * rank raises alike: either because it was decided from data all ranks
   * share, or because share_failure() spread it. main() prints its message
   * once, as one line, and every rank exits with a non-zero code; no rank
   * is left waiting in a collective call.
   */
  class RunError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Collective: every rank of @p communicator passes the message of the
   * failure it met (empty: none). If any rank failed, all ranks throw the
   * failure of the lowest such rank, as an InputError if @p input_error of
   * that rank says so, else as a RunError.
   */
  void
  share_failure(const std::string &message,
                bool               input_error,
                MPI_Comm           communicator);

  /**
   * Collective: run @p work on every rank of @p communicator, then share
   * its failure (share_failure()). @p work must not itself call collective
   * operations (a rank that throws early would leave the others waiting).
   */
  template <typename Work>
  void
  collectively(MPI_Comm communicator, Work &&work)
  {
    std::string message;
    bool        input_error = false;
    try
      {
        work();
      }
    catch (const InputError &e)
      {
        message     = e.what();
        input_error = true;
      }
    catch (const std::exception &e)
      {
        message = e.what();
      }
    share_failure(message.empty() && input_error ? "input error" : message,
                  input_error,
                  communicator);
  }

  /// Collective: run @p work on rank 0 of @p communicator alone (e.g. write
  /// a file), then share its failure with all ranks.
  template <typename Work>
  void
  on_root(MPI_Comm communicator, Work &&work)
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    collectively(communicator, [&]() {
      if (rank == 0)
        work();
    });
  }
} // namespace DiskImpact
