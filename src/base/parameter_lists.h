#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  /// The numbers of the comma-separated list entry @p entry of the current
  /// subsection (declared with Patterns::List(Patterns::Double())).
  inline std::vector<double>
  get_double_list(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    return dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(prm.get(entry), ','));
  }

  /// The counts of the comma-separated list entry @p entry of the current
  /// subsection (declared with Patterns::List(Patterns::Integer(1))).
  inline std::vector<unsigned int>
  get_count_list(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    std::vector<unsigned int> counts;
    for (const int n : dealii::Utilities::string_to_int(
           dealii::Utilities::split_string_list(prm.get(entry), ',')))
      counts.push_back(n);
    return counts;
  }
} // namespace DiskImpact
