#include "base/renamed_entries.h"

#include <algorithm>

namespace DiskImpact
{
  namespace
  {
    std::vector<RenamedEntry> &
    registry()
    {
      static std::vector<RenamedEntry> entries;
      return entries;
    }
  } // namespace

  void
  declare_renamed_entry(dealii::ParameterHandler &prm,
                        const std::string        &subsection,
                        const std::string        &new_name,
                        const std::string        &old_name)
  {
    prm.declare_alias(new_name, old_name);
    auto &entries = registry();
    // Parameters are declared once per ParameterHandler; record each
    // renaming once.
    if (std::none_of(entries.begin(), entries.end(), [&](const auto &e) {
          return e.subsection == subsection && e.old_name == old_name;
        }))
      entries.push_back({subsection, old_name, new_name});
  }

  const std::vector<RenamedEntry> &
  renamed_entries()
  {
    return registry();
  }
} // namespace DiskImpact
