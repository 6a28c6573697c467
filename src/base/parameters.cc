#include "base/parameters.h"

#include "base/input_error.h"

#include <filesystem>
#include <regex>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    RunParameters::declare_parameters(prm);
    DiskGeometry::declare_parameters(prm);
    Material::declare_parameters(prm);
    FiniteElementParameters::declare_parameters(prm);
    ModalSolver::declare_parameters(prm);
    ModalConvergenceStudy::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    QuasistaticContact::declare_parameters(prm);
    TimeIntegrator::declare_parameters(prm);
    Impact::declare_parameters(prm);
    ImpactConvergenceStudy::declare_parameters(prm);
    ReferenceModels::declare_parameters(prm);
    ModalExpansionStudy::declare_parameters(prm);
  }

  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    run.parse_parameters(prm);
    geometry.parse_parameters(prm);
    material.parse_parameters(prm);
    finite_element.parse_parameters(prm);
    modal_solver.parse_parameters(prm);
    modal_convergence.parse_parameters(prm);
    contact.parse_parameters(prm);
    quasistatic_contact.parse_parameters(prm);
    time_integrator.parse_parameters(prm);
    impact.parse_parameters(prm);
    impact_convergence.parse_parameters(prm);
    reference_models.parse_parameters(prm);
    modal_expansion.parse_parameters(prm);

    // Checks across subsections.
    if (run.task == Task::quasistatic_contact)
      {
        require(geometry.is_half_disk(),
                "Task 'quasistatic contact' needs 'Domain = half disk' (the "
                "symmetry condition holds the rigid motions the wall does "
                "not)");
        contact.check_wall(geometry, 0.);
        require(contact.law_kind() == WallLawKind::penalty,
                "Task 'quasistatic contact' needs 'Law = penalty' in "
                "subsection Contact");
      }
    if (run.task == Task::reference_models)
      reference_models.check_velocities(
        impact.contact_law_constant_value(material.in_plane_poisson_ratio()));
    if (run.task == Task::impact || run.task == Task::impact_convergence ||
        run.task == Task::sweep)
      contact.check_wall(geometry, 0.05);
  }

  void
  read_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    require(std::filesystem::is_regular_file(filename),
            "parameter file '" + filename + "' does not exist");
    try
      {
        prm.parse_input(filename);
      }
    catch (const ExceptionBase &e)
      {
        // deal.II's message spans several lines: fold it into one.
        std::ostringstream info;
        e.print_info(info);
        std::string message =
          std::regex_replace(info.str(), std::regex("\\s+"), " ");
        message = std::regex_replace(message, std::regex("^ | $"), "");
        throw InputError("in parameter file '" + filename + "': " + message);
      }
  }
} // namespace DiskImpact
