#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /// Which reduced collision model 'Task = reference models' tabulates.
  enum class ReferenceModel
  {
    disk,    ///< log law with Kelvin-Voigt dissipation (Schwager 2007)
    dashpot, ///< linear spring and dashpot (Schwager & Pöschel 2007)
    spheres, ///< viscoelastic Hertz spheres (Ramírez et al. 1999)
    rayleigh ///< vibration left by the quasistatic collision (Gerl & Zippelius
             ///< 1999, §5)
  };

  /**
   * Task 'reference models' (subsection "Reference models"): epsilon of a
   * reduced collision model (src/reference/) on a grid of its parameters,
   * without finite elements, written to reference_<model>.csv:
   * - disk: for every v/c of 'Velocities' and tau = alpha of 'Relaxation
   * times', the 1-DOF ODE m xi'' + F + A xi' F' = 0 with the log law (constant
   * of subsection Impact, nu2 of subsection Material) ended by the force
   *   (Schwager & Pöschel 2007) and by the overlap, and Schwager's eqs. 56 and
   * 80;
   * - dashpot: for every beta / omega0 of 'Damping ratios', eq. 21 of Schwager
   * & Pöschel 2007 (corrected), the ODE, and the naive overlap criterion;
   * - spheres: for every g / g* of 'Velocity ratios', the ODE, the series
   *   eq. 32 and the Pade approximant eq. 35 of Ramírez et al. 1999;
   * - rayleigh: for every v/c of 'Velocities' and N of 'Mode counts', the
   *   energy the quasistatic 1-DOF force leaves in the N lowest free-disk
   *   modes (Gerl & Zippelius 1999, eqs. 62-68) and the epsilon it implies, the
   * v -> 0 limit of the elastic FE impact.
   */
  class ReferenceModels
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Model 'rayleigh' needs speeds the log law with @p law_constant can
    /// stop (Schwager 2007, eq. 50); an input error otherwise.
    void
    check_velocities(double law_constant) const;

    /// Tabulate the chosen model (rank 0 writes the file).
    void
    run(const Parameters &parameters, MPI_Comm communicator) const;

    /// The tables of the models other than the chosen one: a run leaves
    /// them in its output directory (each model writes its own file).
    std::vector<std::string>
    other_models_files() const;

  private:
    /// Compute the chosen model and write its table (on this rank).
    void
                              tabulate(const Parameters &parameters) const;
    ReferenceModel            model = ReferenceModel::disk;
    std::vector<double>       velocities;
    std::vector<double>       alphas;
    std::vector<double>       damping_ratios;
    std::vector<double>       velocity_ratios;
    std::vector<unsigned int> mode_counts;

    void
    tabulate_disk(const Parameters  &parameters,
                  const std::string &filename) const;
    void
    tabulate_dashpot(const std::string &filename) const;
    void
    tabulate_spheres(const std::string &filename) const;
    void
    tabulate_rayleigh(const Parameters  &parameters,
                      const std::string &filename) const;
  };
} // namespace DiskImpact
