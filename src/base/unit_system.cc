#include "base/unit_system.h"

#include "base/input_error.h"
#include "base/parameter_lists.h"

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
      "time' and 'Relaxation times' [s], viscosities [Pa s], 'Yield stress' "
      "and 'Hardening modulus' [Pa], 'Wall point' [m], 'Time step' [s], speeds "
      "('Velocity', 'Velocities', 'Reference "
      "speed') [m/s], 'Spin' [rad/s]; the run prints SI and dimensionless "
      "results.");
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
  UnitSystem::set_si_scales(const double radius,
                            const double young_modulus,
                            const double density,
                            const double velocity_unit,
                            const double force_unit,
                            const bool   sphere)
  {
    require_in_range("Radius", radius, 1e-9, 1e3, "m");
    require_in_range("Young modulus", young_modulus, 1e3, 1e13, "Pa");
    require_in_range("Density", density, 10., 1e5, "kg/m^3");
    length_scale = radius;
    young_si     = young_modulus;
    density_si   = density;
    speed_scale  = velocity_unit;
    time_scale   = radius / velocity_unit;
    force_scale  = force_unit;
    // The unit of time of the run's inputs, R sqrt(rho/E): 1 with
    // E = rho = R = 1.
    input_time_scale = radius * std::sqrt(density / young_modulus);
    force_unit_name  = sphere ? "N" : "N/m";
    si               = true;
  }

  void
  UnitSystem::make_dimensionless(ParameterHandler &prm) const
  {
    const double own_time = input_time_scale;
    prm.enter_subsection("Geometry");
    prm.set("Radius", "1");
    prm.leave_subsection();
    prm.enter_subsection("Material");
    prm.set("Young modulus", "1");
    prm.set("Density", "1");
    prm.leave_subsection();
    divide(prm, "Material", "Relaxation time", own_time);
    divide(prm, "Material", "Shear viscosity", young_si * own_time);
    divide(prm, "Material", "Bulk viscosity", young_si * own_time);
    divide(prm, "Material", "Yield stress", young_si);
    divide(prm, "Material", "Hardening modulus", young_si);
    divide(prm, "Contact", "Wall point", length_scale);
    divide(prm, "Time stepping", "Time step", own_time);
    divide(prm, "Impact", "Velocity", speed_scale);
    divide(prm, "Impact", "Velocities", speed_scale);
    divide(prm, "Impact", "Spin", 1. / time_scale);
    divide(prm, "Impact", "Relaxation times", own_time);
    divide(prm, "Restitution law", "Reference speed", speed_scale);
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
