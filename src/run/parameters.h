#pragma once

#include "base/parameter_file.h"
#include "base/run_parameters.h"
#include "base/unit_system.h"
#include "body/geometry.h"
#include "body/partner.h"
#include "contact/contact.h"
#include "dynamics/time_integrator.h"
#include "elasticity/elasticity_operator.h"
#include "material/material.h"
#include "modal/modal_solver.h"
#include "run/impact_convergence_parameters.h"
#include "run/impact_parameters.h"
#include "run/task_registry.h"

#include <deal.II/base/parameter_handler.h>

#include <any>
#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * All parameters of a run. Each member declares and parses its own
   * subsection; this struct only collects them.
   */
  struct Parameters
  {
    /// The largest lambda/mu of a body meshed with Q1 elements before
    /// warn_of_locking() warns: 9, nu = 0.45. Measured on a plane-strain
    /// impact at v = 0.05c (2 global refinements): epsilon of Q1 differs
    /// from Q2 by 1.0e-3 at nu = 0.3, 3.8e-3 at 0.45, 6.1e-3 at 0.49,
    /// 4.5e-2 at 0.499, and delta_max of Q1 is 31 % below the 1-DOF
    /// model's at 0.49999.
    static constexpr double max_linear_lambda_over_mu = 9.;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse @p prm; an SI run is parsed as its dimensionless equivalent.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The task 'Task' names.
    const TaskEntry &
    task() const;
    /// The task's own subsection as its entry parsed it (a @p T).
    template <typename T>
    const T &
    task_parameters() const
    {
      return std::any_cast<const T &>(own_parameters);
    }

    RunParameters               run;
    UnitSystem                  units;
    BodyGeometry                geometry;
    Material                    material;
    Partner                     partner;
    FiniteElementParameters     finite_element;
    ModalSolver                 modal_solver;
    ContactParameters           contact;
    TimeIntegrator              time_integrator;
    ImpactParameters            impact;
    ImpactConvergenceParameters impact_convergence;

    /// The task's own subsection, parsed (TaskEntry::parse_parameters).
    std::any own_parameters;

    /// Warnings about the combination of entries (e.g. elements that lock),
    /// one line each, for main() to print; the run goes on.
    std::vector<std::string> warnings;

  private:
    /// Everything but 'Task', 'Output directory' and 'Units'.
    void
    parse_physics(dealii::ParameterHandler &prm);
    /// The limits of a deformable collision partner (subsection Partner).
    void
    check_partner() const;
    /// An elastic-plastic body: a task, model and contact law that
    /// compute it.
    void
    check_plasticity() const;
    /// A warning if linear elements meet a nearly incompressible body.
    void
    warn_of_locking();
  };
} // namespace DiskImpact
