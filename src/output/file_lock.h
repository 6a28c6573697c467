#pragma once

#include <string>

namespace DiskImpact
{
  /**
   * An advisory lock (flock(2)) on a file, created if missing, held while
   * the object lives. The operating system releases it when the process
   * ends in whatever way, a kill included. Other processes (other MPI
   * ranks, other runs) taking a lock on the same file wait or fail.
   */
  class FileLock
  {
  public:
    /// Wait for the lock on @p filename; throws std::runtime_error if the
    /// file cannot be opened.
    explicit FileLock(const std::string &filename);

    /// The lock on @p filename if no other process holds it: @p held tells.
    FileLock(const std::string &filename, bool &held);

    ~FileLock();
    FileLock(const FileLock &) = delete;
    FileLock &
    operator=(const FileLock &) = delete;

  private:
    void
    open(const std::string &filename);

    int descriptor = -1;
  };
} // namespace DiskImpact
