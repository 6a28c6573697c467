#include "base/run_parameters.h"

#include "base/input_error.h"

#include <algorithm>
#include <map>

namespace DiskImpact
{
  using namespace dealii;

  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Task",
      "modal analysis",
      Patterns::Selection(
        "modal analysis|modal convergence|quasistatic contact|impact|"
        "impact convergence|sweep|reference models|modal expansion impact|"
        "restitution law"),
      "What to compute. 'modal analysis': the lowest modes of "
      "the free disk compared with the analytic Bessel modes "
      "(modes.csv). 'modal convergence': the same on a "
      "sequence of meshes and degrees, with observed orders "
      "(modal_convergence.csv). 'quasistatic contact': a half "
      "disk pressed on the wall by a body force, the contact "
      "law delta(P) (contact_law.csv). 'impact': the disk hits "
      "the wall with speed v (impact.csv, summary.csv). 'impact "
      "convergence': that impact on ever finer meshes, time steps "
      "and penalties, epsilon extrapolated with its error bar "
      "(impact_convergence.csv, epsilon_estimate.csv). 'sweep': "
      "epsilon(v) for the velocities of subsection Impact "
      "(restitution.csv). 'reference models': epsilon of a reduced "
      "collision model, no finite elements (subsection Reference models, "
      "reference_<model>.csv). 'modal expansion impact': the impact "
      "in the modal expansion of Gerl & Zippelius 1999 with its smooth wall "
      "potential, "
      "extrapolated to all modes and hard contact (subsection Modal "
      "expansion, modal_expansion.csv, modal_extrapolation.csv). "
      "'restitution law': the sweep with its convergence studies, then "
      "epsilon(v) fitted and stated as input for DEM codes (subsection "
      "Restitution law; restitution_law.csv, restitution_law.json, "
      "dem/).");
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
    const std::map<std::string, Task> tasks{
      {"modal analysis", Task::modal_analysis},
      {"modal convergence", Task::modal_convergence},
      {"quasistatic contact", Task::quasistatic_contact},
      {"impact", Task::impact},
      {"impact convergence", Task::impact_convergence},
      {"sweep", Task::sweep},
      {"reference models", Task::reference_models},
      {"modal expansion impact", Task::modal_expansion_impact},
      {"restitution law", Task::restitution_law}};
    const std::string name = prm.get("Task");
    task                   = tasks.at(name);
    output_directory       = prm.get("Output directory");
    if (output_directory.empty())
      {
        std::string directory = name;
        std::replace(directory.begin(), directory.end(), ' ', '_');
        output_directory = "output/" + directory;
      }
  }

  bool
  RunParameters::runs_sweep() const
  {
    return task == Task::sweep || task == Task::restitution_law;
  }
} // namespace DiskImpact
