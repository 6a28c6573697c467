#pragma once

#include "dynamics/richardson.h"
#include "reference/modal_expansion_impact.h"

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'modal expansion impact' (subsection "Modal expansion"): epsilon
   * of the disk's collision with the smooth wall potential in the modal
   * expansion of Gerl & Zippelius 1999 (Reference::ModalExpansionImpact), for
   * every in-plane Poisson ratio, velocity, wall stiffness alpha and number of
   * modes N of the lists, then extrapolated as Gerl & Zippelius do: for each
   * alpha to N -> infinity by a fit linear in 1/sqrt(N), then to hard
   * contact by a fit linear in 1/alpha. Writes modal_expansion.csv (every
   * run), modal_expansion_modes.csv (the modes of largest average energy of
   * the runs with the largest N, as Gerl & Zippelius' Table 1) and
   * modal_extrapolation.csv (the fits, with their residuals and error
   * bars). The runs are shared out among the MPI ranks.
   */
  class ModalExpansionStudy
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    void
    run(const Parameters &parameters, MPI_Comm communicator) const;

  private:
    std::vector<double>        velocities;
    std::vector<double>        alphas;
    std::vector<unsigned int>  mode_counts;
    std::vector<double>        poisson_ratios;
    unsigned int               angular_points   = 256;
    double                     steps_per_period = 40.;
    Reference::ModalIntegrator integrator;
    unsigned int               mode_rows = 10;
  };
} // namespace DiskImpact
