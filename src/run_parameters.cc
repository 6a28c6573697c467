#include "run_parameters.h"

#include "input_error.h"

namespace DiskImpact
{
  using namespace dealii;

  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Task",
                      "modal analysis",
                      Patterns::Selection("modal analysis|modal convergence"),
                      "What to compute. 'modal analysis': the lowest modes of "
                      "the free disk compared with the analytic Bessel modes "
                      "(modes.csv). 'modal convergence': the same on a "
                      "sequence of meshes and degrees, with observed orders "
                      "(modal_convergence.csv).");
    prm.declare_entry("Output directory",
                      "output/modal",
                      Patterns::Anything(),
                      "Directory for all results (created if missing); it "
                      "receives a copy of the parameters used.");
  }

  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    const std::string name = prm.get("Task");
    task                   = (name == "modal analysis") ? Task::modal_analysis :
                                                          Task::modal_convergence;
    output_directory       = prm.get("Output directory");
    require(!output_directory.empty(), "'Output directory' must not be empty");
  }
} // namespace DiskImpact
