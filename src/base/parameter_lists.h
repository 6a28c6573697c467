#pragma once

#include "base/input_error.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /// The items of the comma-separated list entry @p entry of the current
  /// subsection; an empty item ("0.1,", "0.1,,0.2") is an InputError, which
  /// deal.II's list pattern lets through.
  inline std::vector<std::string>
  get_list_items(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    const std::string text = prm.get(entry);
    if (dealii::Utilities::trim(text).empty())
      return {};
    std::vector<std::string> items;
    std::size_t              start = 0;
    while (true)
      {
        const std::size_t comma = text.find(',', start);
        const std::string item  = dealii::Utilities::trim(
          text.substr(start,
                      comma == std::string::npos ? comma : comma - start));
        require(!item.empty(),
                "'" + entry + "' has an empty item (a comma too many): '" +
                  text + "'");
        items.push_back(item);
        if (comma == std::string::npos)
          return items;
        start = comma + 1;
      }
  }

  /// The numbers of the comma-separated list entry @p entry of the current
  /// subsection (declared with Patterns::List(Patterns::Double())).
  inline std::vector<double>
  get_double_list(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    return dealii::Utilities::string_to_double(get_list_items(prm, entry));
  }

  /// The non-negative integers of the comma-separated list entry @p entry
  /// of the current subsection (declared with
  /// Patterns::List(Patterns::Integer(0 or 1))).
  inline std::vector<unsigned int>
  get_count_list(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    std::vector<unsigned int> counts;
    for (const int n :
         dealii::Utilities::string_to_int(get_list_items(prm, entry)))
      counts.push_back(n);
    return counts;
  }
} // namespace DiskImpact
