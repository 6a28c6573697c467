#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * Read @p filename into @p prm, its 'include FILE' lines replaced by
   * FILE (relative to the working directory, else to the including file). A
   * missing file, an include cycle, an unknown or misspelled entry or a
   * value that does not match its pattern throws an InputError with a
   * one-line message naming the file, the line and the entry. Returns one
   * notice per entry set by an old name (renamed_entries()), naming the
   * file, the line and the new name.
   */
  std::vector<std::string>
  read_parameter_file(dealii::ParameterHandler &prm,
                      const std::string        &filename);
} // namespace DiskImpact
