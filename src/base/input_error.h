#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

  /// @p value with @p digits significant digits, for messages
  /// ("2.4e+08").
  inline std::string
  approximately(const double value, const int digits = 2)
  {
    std::ostringstream text;
    text.precision(digits);
    text << value;
    return text.str();
  }

  /// Throw an InputError with @p message unless @p condition holds.
  inline void
  require(const bool condition, const std::string &message)
  {
    if (!condition)
      throw InputError(message);
  }

  /// Throw an InputError unless @p valid holds for every entry of
  /// @p values; the message is @p what followed by the first bad entry.
  template <typename Predicate>
  inline void
  require_each(const std::vector<double> &values,
               const Predicate           &valid,
               const std::string         &what)
  {
    for (const double value : values)
      if (!valid(value))
        {
          std::ostringstream message;
          message << what << ", got " << value;
          throw InputError(message.str());
        }
  }
} // namespace DiskImpact
