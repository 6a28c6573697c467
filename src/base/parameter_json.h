#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DiskImpact
{
  /**
   * The parameters of @p prm as JSON in deal.II's @p style (JSON or
   * ShortJSON), as provenance for result files: without the aliases that
   * keep old parameter names readable (renamed_entries()), and valid UTF-8
   * whatever bytes a value holds: a byte that is not part of a UTF-8
   * character (e.g. a file name in another encoding) is written as the
   * four characters \xNN.
   */
  std::string
  parameters_as_json(const dealii::ParameterHandler       &prm,
                     dealii::ParameterHandler::OutputStyle style);

  /// @p text with each byte that is not part of a valid UTF-8 character
  /// replaced by the text "\\xNN" (a JSON string's escaped backslash, 'x'
  /// and the byte in hexadecimal).
  std::string
  escape_invalid_utf8_for_json(const std::string &text);
} // namespace DiskImpact
