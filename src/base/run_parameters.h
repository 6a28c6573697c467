#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DiskImpact
{
  /// What a run computes.
  enum class Task
  {
    modal_analysis,
    modal_convergence,
    quasistatic_contact,
    impact,
    impact_convergence,
    sweep,
    reference_models,
    modal_expansion_impact,
    restitution_law
  };

  /**
   * The top-level entries of a parameter file: which task to run and where
   * its results go.
   */
  struct RunParameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Whether the task runs the sweep ('sweep', 'restitution law').
    bool
    runs_sweep() const;

    Task        task = Task::modal_analysis;
    std::string output_directory;
    /// Every parameter of the run as JSON (set by parse_parameters()): the
    /// provenance result files carry.
    std::string parameters_json;
  };
} // namespace DiskImpact
