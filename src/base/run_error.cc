#include "base/run_error.h"

#include <deal.II/base/mpi.h>

namespace DiskImpact
{
  void
  share_failure(const std::string &message,
                const bool         input_error,
                MPI_Comm           communicator)
  {
    // Each rank's failure as one string: its kind ('I'nput or 'R'un) and
    // its message; empty if none.
    const std::string mine =
      message.empty() ? "" : (input_error ? "I" : "R") + message;
    for (const auto &failure :
         dealii::Utilities::MPI::all_gather(communicator, mine))
      if (!failure.empty())
        {
          if (failure[0] == 'I')
            throw InputError(failure.substr(1));
          throw RunError(failure.substr(1));
        }
  }
} // namespace DiskImpact
