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
} // namespace DiskImpact
