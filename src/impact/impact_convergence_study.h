#pragma once

#include "dynamics/richardson.h"
#include "impact/impact_summary.h"
#include "run/impact_convergence_parameters.h"

#include <mpi.h>

#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace DiskImpact
{
  struct Parameters;
  struct ImpactOperatorsBase;
  class CsvTable;

  /// One run of a convergence study.
  struct StudyRun
  {
    /// "mesh", "time step", "penalty", or "split": the mesh of mesh level
    /// l - 1 with the time step of level l
    std::string  factor;
    unsigned int level = 0;
    /// "mesh" and "split": the time step halved this many more times than
    /// the level's own
    unsigned int  time_halvings = 0;
    ImpactSummary summary;
    double        wall_time = 0.; ///< whole run [s]
  };

  /// epsilon of one impact with its error bar, and how it was found.
  struct ConvergedEpsilon
  {
    double                epsilon = 0.; ///< extrapolated
    double                error = 0.; ///< the mesh sequence's (or the split's)
    ImpactSummary         base;       ///< the coarsest run
    std::vector<StudyRun> runs;
    std::vector<std::string>        factors;
    std::vector<RichardsonEstimate> estimates; ///< per factor
    /// With a split run: the last difference's time-step part d_t and mesh
    /// part d_h (NaN without)
    double time_part = std::numeric_limits<double>::quiet_NaN();
    double mesh_part = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * Convergence study of epsilon for one impact (subsection "Impact
   * convergence"): from the base run of the parameter file, refine one
   * discretization parameter at a time, each with a few levels:
   *   mesh:      global refinements + l, elements across the contact * 2^l,
   *              grading / 2^l (every element size halved; the penalty
   *              k = kappa E2 / h doubles) and dt / 2^l: a finer mesh
   *              carries higher frequencies, which a fixed step does not
   *              resolve (docs/theory/impact-method.md); ratio 2, expected
   *              order 1 (the penalty's gap error, proportional to 1/k,
   *              i.e. to h);
   *              from a 'Degree levels from' level L0 on, the mesh of
   *              level L0 - 1 with the degree raised by l - L0 + 1 and the
   *              penalty factor doubled as often (k doubles per level);
   *   time step: dt / 2^l, ratio 2, expected order 2;
   *   penalty:   penalty factor * 4^l, ratio 4 in 1/k, expected order 1.
   * Each sequence is extrapolated (richardson_estimate()). The mesh
   * sequence refines everything together: epsilon and its error bar are
   * its limit and GCI; the other two are diagnostics. With a target error,
   * mesh levels are added one at a time while the mesh sequence's error
   * bar exceeds it, up to a largest number of levels. With the time step's
   * and the mesh's parts of the last difference measured apart ("split"),
   * the study may instead halve the time step of its last two mesh levels
   * where the time step's part is the one that keeps the bar large.
   */
  class ImpactConvergenceStudy : private ImpactConvergenceParameters
  {
  public:
    explicit ImpactConvergenceStudy(
      const ImpactConvergenceParameters &parameters)
        : ImpactConvergenceParameters(parameters)
    {
    }

    /// The study at the velocity of @p parameters, its runs shared out
    /// among the ranks of @p communicator (each run on one rank); @p log
    /// (if not null) receives one line per run of this rank as it ends.
    ConvergedEpsilon
    run(const Parameters &parameters,
        MPI_Comm          communicator,
        std::ostream     *log) const;

    /// @p parameters refined as the study's finest mesh level (with a
    /// target error, the largest level it may add): its largest
    /// discretization.
    Parameters
    finest(const Parameters &parameters) const;

    /// The runs as a table (factor, level, epsilon, ...).
    static CsvTable
    runs_table(const ConvergedEpsilon &result);
    /// One row per factor (order, limit, error) and one for the total.
    static CsvTable
    estimates_table(const ConvergedEpsilon &result);
    /// One line of the log: factor, level, DoFs, time step, epsilon, energy
    /// error, wall time.
    static std::string
    describe(const StudyRun &run);

  private:
    /// The operators of this rank's runs by mesh level (a degree level
    /// counts as one): the runs on one mesh differ only in their time step
    /// (refined()), so they share the mesh and the assembled operators.
    using SharedOperators = std::map<int, std::shared_ptr<ImpactOperatorsBase>>;

    /// Run @p points (described by @p runs) on the ranks of
    /// @p communicator, each on the operators of its mesh level in
    /// @p shared (built by the first run on it); every rank gets all
    /// results.
    static std::vector<StudyRun>
    run_all(const std::vector<StudyRun>   &runs,
            const std::vector<Parameters> &points,
            MPI_Comm                       communicator,
            std::ostream                  *log,
            SharedOperators               &shared);
    /// Each sequence of @p result's runs extrapolated; epsilon and its
    /// error bar from the mesh sequence.
    static void
    estimate(ConvergedEpsilon &result);
    /// Where the mesh sequence is not clean and the split runs of the
    /// finest run exist: the error bar at least 3 (|d_t| + |d_h|), the last
    /// difference's time-step and mesh parts bounded apart (a row "split" of
    /// the estimates); with the time step halved beyond the mesh sequence's,
    /// epsilon is the finest run and this its bar.
    static void
    add_separate_time_step_error(ConvergedEpsilon &result);
    /// The runs that refine @p result next while its bar exceeds the target
    /// (none: stop): a time step halving of the last two mesh levels where
    /// the time step's part of the last difference is at least half the
    /// mesh's (it costs a quarter of a mesh level), else one mesh level
    /// (first the finest mesh at twice its step, where a halving first
    /// skipped it and the choice needs it).
    std::vector<StudyRun>
    next_refinement(const ConvergedEpsilon &result) const;
    /// With 'Halve first above', after the base and split runs: mesh level
    /// 1 at the halved step with its split run where the split's time step
    /// part 3 |d_t| fills that share of the target, else at its own step.
    std::vector<StudyRun>
    second_mesh_level(const ConvergedEpsilon &result) const;
    /// @p parameters with @p factor refined @p level times and the time step
    /// halved @p time_halvings more times.
    Parameters
    refined(const Parameters  &parameters,
            const std::string &factor,
            unsigned int       level,
            unsigned int       time_halvings = 0) const;
  };
} // namespace DiskImpact
