#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * A parameter that was renamed: parameter files may still use its old
   * name, which deal.II reads as the new one (ParameterHandler's alias);
   * read_parameter_file() then gives a one-line notice naming the new name.
   */
  struct RenamedEntry
  {
    /// The subsection path, e.g. "Impact" or "Partner/Material".
    std::string subsection;
    std::string old_name;
    std::string new_name;
  };

  /**
   * Declare @p old_name as an alias of the entry @p new_name of the current
   * subsection of @p prm, which is @p subsection, and record the renaming
   * for renamed_entries().
   */
  void
  declare_renamed_entry(dealii::ParameterHandler &prm,
                        const std::string        &subsection,
                        const std::string        &new_name,
                        const std::string        &old_name);

  /// Every renaming declared so far in this process.
  const std::vector<RenamedEntry> &
  renamed_entries();
} // namespace DiskImpact
