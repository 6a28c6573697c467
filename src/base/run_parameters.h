#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DiskImpact
{
  /**
   * The top-level entries of a parameter file: which task to run (its
   * name; the tasks declare 'Task' themselves) and where its results go.
   */
  struct RunParameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The value of 'Task'.
    std::string task = "modal analysis";
    std::string output_directory;
    /// Every parameter of the run as JSON (set by parse_parameters()): the
    /// provenance result files carry.
    std::string parameters_json;
  };
} // namespace DiskImpact
