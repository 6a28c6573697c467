#include "base/parameters.h"

#include "base/input_error.h"
#include "base/parameter_json.h"
#include "base/renamed_entries.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    RunParameters::declare_parameters(prm);
    UnitSystem::declare_parameters(prm);
    BodyGeometry::declare_parameters(prm);
    Material::declare_parameters(prm);
    Partner::declare_parameters(prm);
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
    RestitutionLaw::declare_parameters(prm);
  }

  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    run.parse_parameters(prm);
    run.parameters_json = parameters_as_json(prm, ParameterHandler::ShortJSON);
    units.parse_parameters(prm);
    if (!units.is_si())
      return parse_physics(prm);
    // The SI entries, mapped to their dimensionless values in a copy: the
    // run's used_parameters keep what the user wrote.
    ParameterHandler dimensionless;
    declare_parameters(dimensionless);
    std::stringstream copy;
    prm.print_parameters(copy, ParameterHandler::PRM);
    dimensionless.parse_input(copy, "the SI parameters");
    units.make_dimensionless(dimensionless, run.task);
    parse_physics(dimensionless);
  }

  void
  Parameters::parse_physics(ParameterHandler &prm)
  {
    geometry.parse_parameters(prm,
                              run.task != Task::modal_analysis &&
                                run.task != Task::modal_convergence);
    material.parse_parameters(prm);
    if (geometry.is_axisymmetric())
      {
        require(!material.plane_model_given(),
                "Material: 'Plane model' is a disk entry; a sphere "
                "(Geometry: 'Body = sphere') is axisymmetric with the 3D "
                "constants (remove 'Plane model')");
        material.make_axisymmetric();
      }
    partner.parse_parameters(prm, geometry, material);
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
    restitution_law.parse_parameters(prm);

    require(geometry.is_axisymmetric() || impact.revolved_view() == 0.,
            "Impact: 'Revolved view' is a sphere's 3D view; a disk's "
            "ParaView output is impact.pvd (set 'Revolved view = 0')");
    require(geometry.is_axisymmetric() || modal_solver.n_torsional_modes() == 0,
            "Modal analysis: 'Torsional modes' are a sphere's azimuthal "
            "modes; a disk's torsional modes (n = 0) are among its in-plane "
            "modes (set 'Torsional modes = 0')");
    // The disk's reduced models (Schwager 2007, Gerl & Zippelius 1999, Schwager
    // & Pöschel 2007) have no sphere version.
    require(!geometry.is_axisymmetric() ||
              (run.task != Task::reference_models &&
               run.task != Task::modal_expansion_impact),
            "Geometry: 'Body = sphere' is not available for the disk's "
            "reduced models (tasks 'reference models' and 'modal "
            "expansion')");

    // Checks across subsections. The scales of the run must be ordinary
    // floating-point numbers, or lengths, masses and energies over- or
    // underflow.
    const double R  = geometry.radius();
    const double E2 = material.in_plane_young_modulus();
    const double c  = material.velocity_unit();
    for (const auto &[name, value] :
         std::vector<std::pair<std::string, double>>{
           {"radius R", R},
           {"in-plane modulus E2", E2},
           {"velocity unit c", c},
           {"mass rho pi R^2", material.density() * M_PI * R * R},
           {"time unit R/c", R / c},
           {"force unit E2 R", E2 * R},
           {"energy unit E2 R^2", E2 * R * R},
           {"stiffness unit E2 / R^2", E2 / (R * R)}})
      require(std::isnormal(value) && value < 1e150 && value > 1e-150,
              "the " + name + " = " + approximately(value) +
                " is outside 1e-150 ... 1e150: choose units in which "
                "'Radius', 'Young modulus' and 'Density' are closer to 1");
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
        impact.contact_law_constant_value(*this));
    if (partner.is_body())
      check_partner();
    else if (run.task == Task::impact || run.task == Task::impact_convergence ||
             run.runs_sweep())
      contact.check_wall(geometry, 0.05);
    if (run.task == Task::impact || run.task == Task::impact_convergence)
      time_integrator.check_time_step(
        impact.estimate_collision(*this).contact_time);
    impact.check_velocities(partner.is_body() ? 1. : 0.5);
    require(partner.is_body() || impact.partner_radii().empty(),
            "Impact: 'Partner radii' needs 'Kind = body' in subsection "
            "Partner");
    if (run.runs_sweep())
      {
        std::vector<Partner> partners{partner};
        if (!impact.partner_radii().empty())
          partners.clear();
        for (const double r2 : impact.partner_radii())
          partners.push_back(partner.with_radius(r2));
        for (const Partner &other : partners)
          for (const double v : impact.velocities())
            {
              Parameters point = *this;
              point.partner    = other;
              point.impact.set_velocity(v);
              time_integrator.check_time_step(
                point.impact.estimate_collision(point).contact_time);
            }
      }
    if (run.runs_sweep())
      {
        require(!impact.velocities().empty(),
                "Impact: 'Velocities' is empty: task 'sweep' needs at least "
                "one impact speed");
        // Every point's material, checked before any point runs.
        const auto in_list = [](const std::string &entry, const auto &check) {
          try
            {
              check();
            }
          catch (const InputError &e)
            {
              throw InputError("Impact: an entry of '" + entry +
                               "' is out of range (" + e.what() + ")");
            }
        };
        for (const double nu : impact.poisson_ratios())
          in_list("Poisson ratios", [&]() { material.with_poisson_ratio(nu); });
        for (const double tau : impact.relaxation_times())
          in_list("Relaxation times",
                  [&]() { material.with_relaxation_time(tau); });
      }
    warn_of_locking();
  }

  void
  Parameters::warn_of_locking()
  {
    // Q1 elements lock (volumetric locking) when the body resists volume
    // change much more than shear: plane strain and the sphere with the 3D
    // nu near 1/2; plane stress cannot (its in-plane bulk modulus stays
    // below 2 mu). lambda/mu = 2 nu / (1 - 2 nu) above 9 (nu > 0.45).
    if (finite_element.degree > 1)
      return;
    std::vector<Material> bodies{material};
    if (partner.is_body())
      bodies.push_back(partner.material());
    if (run.runs_sweep())
      for (const double nu : impact.poisson_ratios())
        bodies.push_back(material.with_poisson_ratio(nu));
    for (const Material &body : bodies)
      {
        const bool three_d_nu = geometry.is_axisymmetric() ||
                                body.plane_model() == PlaneModel::plane_strain;
        const double nu = body.poisson_ratio();
        if (three_d_nu && 2. * nu / (1. - 2. * nu) > max_linear_lambda_over_mu)
          {
            warnings.push_back(
              "Q1 elements ('Degree = 1') lock in a nearly incompressible " +
              std::string(geometry.is_axisymmetric() ? "sphere" :
                                                       "plane-strain disk") +
              " (nu = " + approximately(nu, 6) +
              "): displacements come out too small and epsilon too large; "
              "use 'Degree = 2' or more (subsection Finite element)");
            return;
          }
      }
  }

  void
  Parameters::check_partner() const
  {
    require(run.task == Task::impact || run.task == Task::impact_convergence ||
              run.task == Task::sweep || run.task == Task::quasistatic_contact,
            "Partner: 'Kind = body' is computed by the tasks 'impact', "
            "'impact convergence', 'sweep' and 'quasistatic contact' only");
    require(!units.is_si(),
            "Partner: 'Kind = body' takes dimensionless units (Units = "
            "dimensionless)");
    const RigidWall &wall = contact.wall();
    require(wall.point.norm() == 0. && wall.normal[0] == 1. &&
              wall.normal[1] == 0.,
            "Contact: 'Wall point' and 'Wall normal' must keep their "
            "defaults (0, 0) and (1, 0) with 'Kind = body' in subsection "
            "Partner: the partner's place is set by its 'Gap'");
    require(!geometry.has_mesh_file(),
            "Geometry: a 'Mesh file' cannot be used with 'Kind = body' in "
            "subsection Partner (both bodies use the built-in mesh)");
    require(!time_integrator.redistribute_mass(),
            "Time stepping: 'Contact mass = redistributed' is not available "
            "with 'Kind = body' in subsection Partner");
    require(contact.law_kind() != WallLawKind::constraint,
            "Contact: 'Law = constraint' is not available with 'Kind = body' "
            "in subsection Partner");
    require(impact.revolved_view() == 0.,
            "Impact: 'Revolved view' is a single sphere's output: set it to "
            "0 with 'Kind = body' in subsection Partner");
    require(impact.poisson_ratios().empty() &&
              impact.relaxation_times().empty(),
            "Impact: 'Poisson ratios' and 'Relaxation times' change the "
            "body's material only: give both bodies' materials in "
            "subsections Material and Partner instead");
  }

  namespace
  {
    /** A line of the expanded parameter text and where it comes from. */
    struct SourceLine
    {
      std::filesystem::path file;
      unsigned int          number;
      std::string           text;
    };

    /**
     * The file named by the 'include FILE' line @p line of @p including, or
     * an empty path if @p line is no include line. FILE is taken relative
     * to the working directory if it exists there, else relative to the
     * including file's directory.
     */
    std::filesystem::path
    included_file(const std::string           &line,
                  const std::filesystem::path &including)
    {
      const auto start = line.find_first_not_of(" \t");
      if (start == std::string::npos ||
          (line.compare(start, 8, "include ") != 0 &&
           line.compare(start, 8, "INCLUDE ") != 0))
        return {};
      std::string name = line.substr(start + 8);
      name             = name.substr(0, name.find('#'));
      name             = Utilities::trim(name);
      require(!name.empty(),
              "in parameter file '" + including.string() +
                "': 'include' names no file");
      std::filesystem::path path(name);
      if (!std::filesystem::exists(path) && path.is_relative())
        path = including.parent_path() / name;
      return path;
    }

    /**
     * Append the lines of parameter file @p filename to @p text, each
     * 'include FILE' line replaced by FILE's lines (recursively), and the
     * origin of each line to @p origins. A missing file and an include
     * cycle, which would recurse without end, throw an InputError.
     * @p chain: the files including this one.
     */
    void
    expand_includes(const std::filesystem::path        &filename,
                    std::vector<std::filesystem::path> &chain,
                    std::string                        &text,
                    std::vector<SourceLine>            &origins)
    {
      namespace fs = std::filesystem;
      require(fs::is_regular_file(filename),
              "parameter file '" + filename.string() + "' " +
                (fs::is_directory(filename) ? "is a directory" :
                                              "does not exist") +
                (chain.empty() ?
                   "" :
                   " (included from '" + chain.back().string() + "')"));
      const fs::path canonical = fs::canonical(filename);
      require(std::find(chain.begin(), chain.end(), canonical) == chain.end(),
              "parameter file '" + filename.string() +
                "' includes itself (directly or through other files)");
      chain.push_back(canonical);
      std::ifstream in(filename);
      std::string   line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          const fs::path included = included_file(line, filename);
          if (!included.empty())
            {
              expand_includes(included, chain, text, origins);
              continue;
            }
          text += line + '\n';
          origins.push_back({filename, number, line});
        }
      chain.pop_back();
    }

    /**
     * Throw an InputError if parameter file @p filename has no statement: an
     * empty file would run the defaults, almost surely not what was meant.
     */
    void
    require_a_statement(const std::string &filename)
    {
      std::ifstream    in(filename);
      const std::regex statement(
        "^\\s*(set|SET|include|INCLUDE|subsection)\\s");
      std::string line;
      while (std::getline(in, line))
        if (std::regex_search(line, statement))
          return;
      throw InputError("parameter file '" + filename +
                       "' sets nothing (empty, or comments only): give at "
                       "least 'set Task = ...'");
    }

    /**
     * deal.II's message for a line it could not parse, folded into one
     * line, with the line number of the expanded text replaced by the file
     * and line of @p origins it comes from, and the line quoted (deal.II
     * only numbers it).
     */
    std::string
    one_line_message(const ExceptionBase           &error,
                     const std::vector<SourceLine> &origins)
    {
      std::ostringstream info;
      error.print_info(info);
      std::string message =
        std::regex_replace(info.str(), std::regex("\\s+"), " ");
      message = std::regex_replace(message, std::regex("^ | $"), "");
      std::smatch where;
      if (!std::regex_search(message,
                             where,
                             std::regex("Line <([0-9]+)> of file <[^>]*>")))
        return message;
      const unsigned long n = std::stoul(where[1].str());
      if (n < 1 || n > origins.size())
        return message;
      const SourceLine &origin = origins[n - 1];
      return where.prefix().str() + "Line <" + std::to_string(origin.number) +
             "> of file <" + origin.file.string() + ">" + where.suffix().str() +
             " (the line reads '" + Utilities::trim(origin.text) + "')";
    }

    /**
     * One notice per line of @p origins that sets an entry by its old name
     * (renamed_entries()): "FILE:LINE: 'OLD' (subsection S) is now called
     * 'NEW'". Subsections are followed by their 'subsection' and 'end'
     * lines, as deal.II reads them.
     */
    std::vector<std::string>
    renamed_entry_notices(const std::vector<SourceLine> &origins)
    {
      const std::regex subsection("^\\s*(subsection|SUBSECTION)\\s+(.*?)\\s*$");
      const std::regex end("^\\s*(end|END)\\s*$");
      const std::regex set("^\\s*(set|SET)\\s+(.*?)\\s*=");
      std::vector<std::string> path;
      std::vector<std::string> notices;
      for (const SourceLine &line : origins)
        {
          const std::string text = line.text.substr(0, line.text.find('#'));
          std::smatch       match;
          if (std::regex_search(text, match, subsection))
            path.push_back(match[2].str());
          else if (std::regex_search(text, end) && !path.empty())
            path.pop_back();
          else if (std::regex_search(text, match, set))
            {
              std::string joined;
              for (const std::string &name : path)
                joined += (joined.empty() ? "" : "/") + name;
              for (const RenamedEntry &entry : renamed_entries())
                if (entry.subsection == joined &&
                    entry.old_name == match[2].str())
                  notices.push_back(line.file.string() + ":" +
                                    std::to_string(line.number) + ": '" +
                                    entry.old_name + "' (subsection " +
                                    entry.subsection + ") is now called '" +
                                    entry.new_name + "'");
            }
        }
      return notices;
    }
  } // namespace

  std::vector<std::string>
  read_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    std::vector<std::filesystem::path> chain;
    std::string                        text;
    std::vector<SourceLine>            origins;
    expand_includes(filename, chain, text, origins);
    require_a_statement(filename);
    try
      {
        // deal.II reads 'include' relative to the working directory only;
        // the expanded text also finds a file beside the including one.
        std::istringstream expanded(text);
        prm.parse_input(expanded, filename);
      }
    catch (const ExceptionBase &e)
      {
        throw InputError("in parameter file '" + filename +
                         "': " + one_line_message(e, origins));
      }
    return renamed_entry_notices(origins);
  }
} // namespace DiskImpact
