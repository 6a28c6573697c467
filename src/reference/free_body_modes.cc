#include "reference/free_body_modes.h"

#include <algorithm>

namespace DiskImpact
{
  namespace Reference
  {
    std::string
    to_string(const ModeFamily family)
    {
      switch (family)
        {
          case ModeFamily::rigid:
            return "rigid";
          case ModeFamily::radial:
            return "radial";
          case ModeFamily::torsional:
            return "torsional";
          case ModeFamily::mixed:
            return "mixed";
          case ModeFamily::spheroidal:
            return "spheroidal";
        }
      return "unknown";
    }

    bool
    ModeLabel::operator==(const ModeLabel &other) const
    {
      return n == other.n && l == other.l && family == other.family;
    }

    bool
    ModeLabel::operator<(const ModeLabel &other) const
    {
      if (n != other.n)
        return n < other.n;
      if (family != other.family)
        return family < other.family;
      return l < other.l;
    }

    std::vector<ModeLabel>
    lowest_labels(std::vector<std::pair<double, ModeLabel>> found,
                  const unsigned int                        n_modes)
    {
      std::stable_sort(found.begin(),
                       found.end(),
                       [](const auto &a, const auto &b) {
                         return a.first < b.first;
                       });
      std::vector<ModeLabel> modes;
      for (unsigned int i = 0; i < n_modes && i < found.size(); ++i)
        modes.push_back(found[i].second);
      return modes;
    }
  } // namespace Reference
} // namespace DiskImpact
