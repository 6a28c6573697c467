#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'modal convergence': the modal analysis on a sequence of global
   * refinements for each of several degrees; per analytic mode the relative
   * frequency error at each level and the observed order
   * log(e_{i-1} / e_i) / log(h_{i-1} / h_i). Writes modal_convergence.csv.
   */
  class ModalConvergenceStudy
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    void
    run(const Parameters &parameters, MPI_Comm communicator) const;

    /// @p parameters with the study's largest degree and refinement: its
    /// largest discretization.
    Parameters
    finest(const Parameters &parameters) const;
    /// @p parameters with the study's smallest degree and refinement, and
    /// the number of elastic modes the modes compared take at least.
    Parameters
    coarsest(const Parameters &parameters) const;

  private:
    std::vector<unsigned int> degrees;
    std::vector<unsigned int> refinement_levels;
    unsigned int              n_modes_compared = 10;
  };
} // namespace DiskImpact
