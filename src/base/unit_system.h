#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DiskImpact
{
  /**
   * The factors that turn a run's fields into the units its files are
   * written in: 1 for a dimensionless run; for an SI run R [m] for lengths
   * (coordinates, displacements), E [Pa] for stresses, R/c [s] for the
   * times of a record (which are in units of R/c).
   */
  struct FieldScales
  {
    double length = 1.;
    double stress = 1.;
    double time   = 1.;
  };

  /**
   * The top-level entry 'Units': 'dimensionless' (the default: any
   * consistent units, speeds in units of c) or 'SI' (a real particle:
   * radius in m, Young modulus in Pa, density in kg/m^3, times in s,
   * viscosities in Pa s, speeds in m/s).
   *
   * An SI run is solved as the equivalent dimensionless run: its entries
   * are mapped to R = E = rho = 1, speeds to v/c and times to units of
   * R sqrt(rho/E) before any other class parses them, so both give the same
   * numbers; the scales turn the dimensionless results back into SI.
   */
  class UnitSystem
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    bool
    is_si() const;

    /**
     * Make this an SI run with the scales of its body: radius @p radius
     * [m], Young modulus @p young_modulus [Pa], density @p density
     * [kg/m^3], velocity unit c = @p velocity_unit [m/s] and force unit
     * @p force_unit [N for a sphere, N/m for a disk]. Throws an InputError
     * for values that look dimensionless (R, E or rho far from a real
     * particle's).
     */
    void
    set_si_scales(double radius,
                  double young_modulus,
                  double density,
                  double velocity_unit,
                  double force_unit,
                  bool   sphere);

    /**
     * SI only: set the dimensionless values of the SI entries of @p prm:
     * R = E = rho = 1, speeds in units of c, times in units of
     * R sqrt(rho/E), the wall point in units of R.
     */
    void
    make_dimensionless(dealii::ParameterHandler &prm) const;

    /// SI values of the dimensionless units (SI only): R [m], R/c [s],
    /// c [m/s], the force unit [N for a sphere, N/m for a disk].
    double
    length() const;
    double
    time() const;
    double
    speed() const;
    double
    force() const;
    /// The SI value of the time unit of the run's inputs (relaxation
    /// times), R sqrt(rho/E) [s].
    double
    input_time() const;
    /// The SI density [kg/m^3] and Young modulus [Pa] the run was given.
    double
    density() const;
    double
    young_modulus() const;
    /// "N" (sphere) or "N/m" (disk, per unit thickness).
    std::string
    force_name() const;
    /// The scales of the VTU/PVD output (identity unless SI).
    FieldScales
    field_scales() const;

    /// The scales, one line each (SI only).
    void
    print_summary(dealii::ConditionalOStream &out) const;

  private:
    bool   si           = false;
    double length_scale = 1., time_scale = 1., speed_scale = 1.,
           force_scale = 1., density_si = 1., young_si = 1.,
           input_time_scale     = 1.;
    std::string force_unit_name = "N/m";
  };
} // namespace DiskImpact
