#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace DiskImpact
{
  class FileLock;

  /**
   * The output directory of a run: created if missing and locked while the
   * run lives, so that a second run into it refuses with one line; cleared
   * of the results an earlier run left there, so that a run that fails
   * leaves none that look like its own; and given a copy of the parameters
   * used (used_parameters.prm and .json). Every member is collective over
   * the communicator; the file-system work is rank 0's, its failures are
   * shared with all ranks (RunError).
   *
   * The lock is an advisory lock (flock) on the file .diskimpact.lock in the
   * directory, which the operating system releases when the run ends in
   * whatever way, a kill included.
   */
  class OutputDirectory
  {
  public:
    /// Create and lock @p path.
    OutputDirectory(const std::string &path, MPI_Comm communicator);
    ~OutputDirectory();
    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &
    operator=(const OutputDirectory &) = delete;

    /// Remove the files whose names match one of @p patterns (shell
    /// wildcards, fnmatch(3)) and every left-over temporary file (*.tmp),
    /// except the names in @p keep.
    void
    remove_results(const std::vector<std::string> &patterns,
                   const std::vector<std::string> &keep) const;

    /// used_parameters.prm and used_parameters.json, each written whole.
    void
    write_parameters(const dealii::ParameterHandler &prm) const;

    const std::string &
    path() const;

  private:
    std::string path_name;
    MPI_Comm    communicator;
    /// The directory's lock, held on rank 0.
    std::unique_ptr<FileLock> lock;
  };
} // namespace DiskImpact
