#include "run/parameters.h"

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

  namespace
  {
    /**
     * An SI run (Units = SI): check that its task and entries have an SI
     * meaning, record its scales in @p units from its body (the radius,
     * Young modulus and density of @p prm, the velocity unit and force
     * unit of its material) and set the dimensionless values in @p prm.
     */
    void
    make_si_dimensionless(ParameterHandler &prm,
                          const TaskEntry  &task,
                          UnitSystem       &units)
    {
      require(task.traits.impacts,
              "Units = SI is for the impact tasks ('impact', 'impact "
              "convergence', 'sweep', 'restitution law'); this task takes "
              "dimensionless input (set 'Units = dimensionless')");
      prm.enter_subsection("Geometry");
      require(prm.get("Mesh file").empty(),
              "Units = SI takes the built-in meshes; a 'Mesh file' is in "
              "units of R (set 'Units = dimensionless')");
      prm.leave_subsection();
      prm.enter_subsection("Impact");
      require(prm.get("Poisson ratios").empty(),
              "Units = SI: 'Poisson ratios' is a dimensionless study (the "
              "speed unit c changes with nu); give one 'Poisson ratio' in "
              "subsection Material");
      prm.leave_subsection();

      BodyGeometry geometry;
      geometry.parse_parameters(prm);
      Material material;
      material.parse_parameters(prm);
      const bool sphere = geometry.is_sphere();
      if (sphere && !material.plane_model_given())
        material.make_axisymmetric();
      const double R = geometry.radius();
      units.set_si_scales(R,
                          material.young_modulus(),
                          material.density(),
                          material.velocity_unit(),
                          material.in_plane_young_modulus() * R *
                            (sphere ? R : 1.),
                          sphere);
      units.make_dimensionless(prm);
    }
  } // namespace

  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    Tasks::declare_parameters(prm);
    RunParameters::declare_parameters(prm);
    UnitSystem::declare_parameters(prm);
    BodyGeometry::declare_parameters(prm);
    Material::declare_parameters(prm);
    Partner::declare_parameters(prm);
    FiniteElementParameters::declare_parameters(prm);
    ModalSolver::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    TimeIntegrator::declare_parameters(prm);
    ImpactParameters::declare_parameters(prm);
    ImpactConvergenceParameters::declare_parameters(prm);
    Tasks::declare_own_parameters(prm);
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
    make_si_dimensionless(dimensionless, task(), units);
    parse_physics(dimensionless);
  }

  void
  Parameters::parse_physics(ParameterHandler &prm)
  {
    geometry.parse_parameters(prm, !task().traits.modal);
    material.parse_parameters(prm);
    if (geometry.dimension() == 3 && !task().traits.three_dimensional)
      {
        std::string names;
        for (const auto &entry : Tasks::all())
          if (entry.traits.three_dimensional)
            names += (names.empty() ? "'" : ", '") + entry.name + "'";
        throw InputError("Geometry: 'Dimension = 3' is computed by the "
                         "tasks " +
                         names + " so far; task '" + run.task +
                         "' takes 'Dimension = 2'");
      }
    require(geometry.dimension() == 2 || !geometry.has_symmetry_plane_z() ||
              !task().traits.modal || geometry.body() == Body::disk,
            "Geometry: a quarter or half sphere holds only the modes "
            "symmetric about its planes, which are not whole multiplets; a "
            "modal analysis of the sphere in 3D takes 'Domain = full "
            "sphere'");
    if (geometry.body() == Body::sphere)
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
    contact.parse_parameters(prm);
    time_integrator.parse_parameters(prm);
    // The massless edge zone is a disk about the contact point: a disk's
    // rim in 3D touches along a line.
    require(geometry.dimension() == 2 || geometry.is_sphere() ||
              (!contact.exact_constraint() &&
               !time_integrator.redistribute_mass()),
            "Contact: 'Law = constraint' and 'Contact mass = redistributed' "
            "are not available for a disk in 3D so far");
    impact.parse_parameters(prm);
    require(!impact.conforming_mesh() ||
              (!partner.is_body() &&
               !(geometry.dimension() == 3 && geometry.is_sphere())),
            "Impact: 'Graded mesh = conforming' takes one body against the "
            "wall, a disk or the sphere's meridian (the sphere in 3D is "
            "refined with hanging nodes)");
    require(impact.layer_refinement() == 0 ||
              (geometry.dimension() == 3 && !geometry.is_sphere() &&
               impact.conforming_mesh()),
            "Impact: 'Layer refinement' grades the layers of a disk in 3D "
            "on 'Graded mesh = conforming'; set it to 0 here");
    impact_convergence.parse_parameters(prm);
    // Every task's own subsection is checked; the chosen task's is kept.
    for (const auto &entry : Tasks::all())
      if (entry.parse_parameters)
        {
          std::any parsed = entry.parse_parameters(prm);
          if (entry.name == run.task)
            own_parameters = std::move(parsed);
        }

    require(geometry.is_axisymmetric() || impact.revolved_view() == 0.,
            geometry.dimension() == 3 ?
              "Impact: 'Revolved view' is the meridian's 3D view; a 3D "
              "body's ParaView output is impact.pvd (set 'Revolved view = "
              "0')" :
              "Impact: 'Revolved view' is a sphere's 3D view; a disk's "
              "ParaView output is impact.pvd (set 'Revolved view = 0')");
    require(geometry.is_axisymmetric() || modal_solver.n_torsional_modes() == 0,
            geometry.dimension() == 3 ?
              "Modal analysis: 'Torsional modes' are the meridian's azimuthal "
              "modes; the 3D sphere's torsional modes are among its modes "
              "(set 'Torsional modes = 0')" :
              "Modal analysis: 'Torsional modes' are a sphere's azimuthal "
              "modes; a disk's torsional modes (n = 0) are among its "
              "in-plane modes (set 'Torsional modes = 0')");
    // The disk's reduced models (Schwager 2007, Gerl & Zippelius 1999, Schwager
    // & Pöschel 2007) have no sphere version.
    require(!geometry.is_sphere() || task().traits.sphere,
            "Geometry: 'Body = sphere' is not available for the disk's "
            "reduced models (task '" +
              run.task + "')");

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
    if (partner.is_body())
      check_partner();
    else if (task().traits.impacts)
      contact.check_wall(geometry, 0.05);
    impact.check_velocities(partner.is_body() ? 1. : 0.5);
    require(!impact.is_oblique() ||
              (geometry.turns_in_plane() && !partner.is_body()),
            "Impact: an oblique impact ('Angle of incidence' or 'Spin' not "
            "0) is computed for the whole disk in two dimensions (Domain = "
            "full disk, Dimension = 2) or the sphere in three (Domain = "
            "half sphere or full sphere, Dimension = 3) against the wall so "
            "far");
    require(contact.friction_coefficient() == 0. || !partner.is_body(),
            "Contact: 'Friction coefficient' > 0 acts on the wall; a "
            "partner body's contact is frictionless so far");
    require(partner.is_body() || impact.partner_radii().empty(),
            "Impact: 'Partner radii' needs 'Kind = body' in subsection "
            "Partner");
    check_plasticity();
    if (task().check)
      task().check(*this);
    warn_of_locking();
  }

  void
  Parameters::check_plasticity() const
  {
    std::vector<Material> bodies{material};
    if (partner.is_body())
      bodies.push_back(partner.material());
    for (const Material &body : bodies)
      {
        if (!body.is_plastic())
          continue;
        require(task().traits.plasticity,
                "Material: 'Yield stress' > 0 (an elastic-plastic body) is "
                "computed by the tasks impact, sweep, impact convergence and "
                "quasistatic contact so far, not by '" +
                  run.task + "'");
        require(!contact.exact_constraint(),
                "Contact: an elastic-plastic body ('Yield stress' > 0) needs "
                "'Law = penalty' or 'exponential', not 'constraint'");
      }
  }

  const TaskEntry &
  Parameters::task() const
  {
    return Tasks::get(run.task);
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
    if (task().traits.sweeps)
      for (const double nu : impact.poisson_ratios())
        bodies.push_back(material.with_poisson_ratio(nu));
    for (const Material &body : bodies)
      {
        const bool three_d_nu = geometry.is_sphere() ||
                                body.plane_model() == PlaneModel::plane_strain;
        const double nu = body.poisson_ratio();
        if (three_d_nu && 2. * nu / (1. - 2. * nu) > max_linear_lambda_over_mu)
          {
            warnings.push_back(
              "Q1 elements ('Degree = 1') lock in a nearly incompressible " +
              std::string(geometry.is_sphere() ? "sphere" :
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
    std::string tasks;
    for (const auto &entry : Tasks::all())
      if (entry.traits.partner_body)
        tasks +=
          std::string(tasks.empty() ? "" : ", ") + "'" + entry.name + "'";
    require(task().traits.partner_body,
            "Partner: 'Kind = body' is computed by the tasks " + tasks +
              " only");
    require(geometry.dimension() == 2,
            "Partner: 'Kind = body' takes 'Dimension = 2' (subsection "
            "Geometry) so far");
    require(!units.is_si(),
            "Partner: 'Kind = body' takes dimensionless units (Units = "
            "dimensionless)");
    const RigidWall<2> wall = contact.wall();
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
    require(!contact.exact_constraint(),
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

} // namespace DiskImpact
