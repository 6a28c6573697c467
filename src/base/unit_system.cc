#include "base/unit_system.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"
#include "body/geometry.h"
#include "elasticity/material.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// @p values as a parameter list, to full precision.
    std::string
    list_string(const std::vector<double> &values)
    {
      std::ostringstream text;
      text << std::setprecision(17);
      for (std::size_t i = 0; i < values.size(); ++i)
        text << (i > 0 ? ", " : "") << values[i];
      return text.str();
    }

    /// Divide the double list (or single value) at @p path by @p unit.
    void
    divide(ParameterHandler  &prm,
           const std::string &section,
           const std::string &entry,
           const double       unit)
    {
      prm.enter_subsection(section);
      std::vector<double> values = get_double_list(prm, entry);
      for (double &value : values)
        value /= unit;
      prm.set(entry, list_string(values));
      prm.leave_subsection();
    }

    void
    require_in_range(const std::string &entry,
                     const double       value,
                     const double       low,
                     const double       high,
                     const std::string &unit)
    {
      require(value >= low && value <= high,
              "Units = SI: '" + entry + "' = " + approximately(value, 6) + " " +
                unit + " is outside " + approximately(low) + " ... " +
                approximately(high) + " " + unit +
                " (a dimensionless value in an SI run?)");
    }
  } // namespace

  void
  UnitSystem::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Units",
      "dimensionless",
      Patterns::Selection("dimensionless|SI"),
      "'dimensionless': any consistent units, speeds in units of "
      "c = sqrt(E2/rho), results in units of R, R/c and E2 R (disk) or "
      "E* R^2 (sphere). 'SI': a real particle, for the impact tasks: "
      "'Radius' [m], 'Young modulus' [Pa], 'Density' [kg/m^3], 'Relaxation "
      "time' and 'Relaxation times' [s], viscosities [Pa s], 'Wall point' "
      "[m], 'Time step' [s], speeds ('Velocity', 'Velocities', 'Reference "
      "speed') [m/s]; the run prints SI and dimensionless results.");
  }

  void
  UnitSystem::parse_parameters(ParameterHandler &prm)
  {
    si = prm.get("Units") == "SI";
  }

  bool
  UnitSystem::is_si() const
  {
    return si;
  }

  void
  UnitSystem::make_dimensionless(ParameterHandler &prm, const Task task)
  {
    require(task == Task::impact || task == Task::impact_convergence ||
              task == Task::sweep || task == Task::restitution_law,
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
    if (geometry.is_axisymmetric() && !material.plane_model_given())
      material.make_axisymmetric();
    const double R   = geometry.radius();
    const double E   = material.young_modulus();
    const double rho = material.density();
    require_in_range("Radius", R, 1e-9, 1e3, "m");
    require_in_range("Young modulus", E, 1e3, 1e13, "Pa");
    require_in_range("Density", rho, 10., 1e5, "kg/m^3");

    // The run's own unit of time, R sqrt(rho/E) (with E = rho = R = 1 it
    // is 1), and the units of its results.
    const double own_time = R * std::sqrt(rho / E);
    speed_scale           = material.velocity_unit();
    length_scale          = R;
    time_scale            = R / speed_scale;
    force_scale           = material.in_plane_young_modulus() * R *
                  (geometry.is_axisymmetric() ? R : 1.);
    force_unit_name  = geometry.is_axisymmetric() ? "N" : "N/m";
    density_si       = rho;
    input_time_scale = own_time;
    young_si         = E;

    prm.enter_subsection("Geometry");
    prm.set("Radius", "1");
    prm.leave_subsection();
    prm.enter_subsection("Material");
    prm.set("Young modulus", "1");
    prm.set("Density", "1");
    prm.leave_subsection();
    divide(prm, "Material", "Relaxation time", own_time);
    divide(prm, "Material", "Shear viscosity", E * own_time);
    divide(prm, "Material", "Bulk viscosity", E * own_time);
    divide(prm, "Contact", "Wall point", R);
    divide(prm, "Time stepping", "Time step", own_time);
    divide(prm, "Impact", "Velocity", speed_scale);
    divide(prm, "Impact", "Velocities", speed_scale);
    divide(prm, "Impact", "Relaxation times", own_time);
    divide(prm, "Restitution law", "Reference speed", speed_scale);
    si = true;
  }

  double
  UnitSystem::length() const
  {
    return length_scale;
  }

  double
  UnitSystem::time() const
  {
    return time_scale;
  }

  double
  UnitSystem::speed() const
  {
    return speed_scale;
  }

  double
  UnitSystem::force() const
  {
    return force_scale;
  }

  double
  UnitSystem::input_time() const
  {
    return input_time_scale;
  }

  double
  UnitSystem::density() const
  {
    return density_si;
  }

  double
  UnitSystem::young_modulus() const
  {
    return young_si;
  }

  std::string
  UnitSystem::force_name() const
  {
    return force_unit_name;
  }

  FieldScales
  UnitSystem::field_scales() const
  {
    if (!si)
      return {};
    // The run was solved with R = E = rho = 1: its stresses are in units of
    // the SI Young modulus.
    return {length_scale, young_si, time_scale};
  }

  void
  UnitSystem::print_summary(ConditionalOStream &out) const
  {
    if (!si)
      return;
    out << "Units: SI, solved dimensionless with R = " << length_scale
        << " m, c = " << speed_scale << " m/s, R/c = " << time_scale
        << " s, force unit " << force_scale << ' ' << force_unit_name << '\n';
  }
} // namespace DiskImpact
