#pragma once

#include <stdexcept>
#include <string>

namespace DiskImpact
{
  /**
   * An error in what the user asked for (a parameter value, a missing file,
   * an inconsistent combination). main() prints its message as one line and
   * exits with a non-zero code before any result file is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Throw an InputError with @p message unless @p condition holds.
  inline void
  require(const bool condition, const std::string &message)
  {
    if (!condition)
      throw InputError(message);
  }
} // namespace DiskImpact
