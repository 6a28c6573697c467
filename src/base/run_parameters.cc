#include "base/run_parameters.h"

#include "base/input_error.h"

#include <algorithm>

namespace DiskImpact
{
  using namespace dealii;

  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Output directory",
                      "",
                      Patterns::Anything(),
                      "Directory for all results (created if missing); it "
                      "receives a copy of the parameters used. Empty: "
                      "output/TASK, TASK the task's name with '_' for each "
                      "space (output/impact, output/sweep, "
                      "output/restitution_law, ...).");
  }

  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    task             = prm.get("Task");
    output_directory = prm.get("Output directory");
    if (output_directory.empty())
      {
        std::string directory = task;
        std::replace(directory.begin(), directory.end(), ' ', '_');
        output_directory = "output/" + directory;
      }
  }
} // namespace DiskImpact
