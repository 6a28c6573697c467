#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <string>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'restitution law' (subsection "Restitution law"): the sweep over
   * the 'Velocities' of subsection Impact, each point a convergence study,
   * then epsilon(v) in the form a DEM code takes it:
   * - restitution_law.csv: speed, epsilon with its error bar, contact
   *   time, largest compression and peak force, dimensionless and (with
   *   'Units = SI') in SI;
   * - fits with their residuals: a smooth 1 - eps = sum_k a_k (v/v_ref)^{k/5}
   *   for any particle, and the dissipative constant A of the papers'
   *   1-DOF theory (disk: Schwager's, Schwager 2007; sphere: Ramírez et al.
   * 1999) fitted to the FE epsilon(v);
   * - for a sphere in SI, inputs for DEM codes at 'Reference speed' in
   *   dem/ (LIGGGHTS, LAMMPS, Yade, MercuryDPM, Lethe);
   * - restitution_law.json: all of it with the provenance (version,
   *   parameters).
   */
  class RestitutionLaw
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    void
    run(const Parameters &parameters, bool resume, MPI_Comm communicator) const;

  private:
    /// v_ref / c; 0: the geometric mean of the smallest and largest speed.
    double       reference_speed = 0.;
    unsigned int fit_terms       = 3;
  };
} // namespace DiskImpact
