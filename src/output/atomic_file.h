#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace DiskImpact
{
  /**
   * Write the file @p filename whole or not at all: @p contents go to
   * FILENAME.tmp, which is written, synced and closed, each step checked,
   * and only then renamed to FILENAME. A failure (a full disk, a read-only
   * directory, a file-size limit) throws std::runtime_error with one line
   * naming the file and the cause, removes FILENAME.tmp and leaves an older
   * FILENAME as it was.
   */
  void
  write_atomically(const std::string &filename, const std::string &contents);

  /// The same with the contents that @p write puts in a stream (which holds
  /// them in memory until they are written at once).
  void
  write_atomically(const std::string                         &filename,
                   const std::function<void(std::ostream &)> &write);
} // namespace DiskImpact
