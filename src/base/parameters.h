#pragma once

#include "base/run_parameters.h"
#include "base/unit_system.h"
#include "body/geometry.h"
#include "body/partner.h"
#include "contact/contact.h"
#include "dynamics/time_integrator.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/material.h"
#include "modal/modal_solver.h"
#include "tasks/impact.h"
#include "tasks/impact_convergence_study.h"
#include "tasks/modal_convergence_study.h"
#include "tasks/modal_expansion_task.h"
#include "tasks/quasistatic_contact.h"
#include "tasks/reference_models_task.h"
#include "tasks/restitution_law.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DiskImpact
{
  /**
   * All parameters of a run. Each member declares and parses its own
   * subsection; this struct only collects them.
   */
  struct Parameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse @p prm; an SI run is parsed as its dimensionless equivalent.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    RunParameters           run;
    UnitSystem              units;
    BodyGeometry            geometry;
    Material                material;
    Partner                 partner;
    FiniteElementParameters finite_element;
    ModalSolver             modal_solver;
    ModalConvergenceStudy   modal_convergence;
    ContactParameters       contact;
    QuasistaticContact      quasistatic_contact;
    TimeIntegrator          time_integrator;
    Impact                  impact;
    ImpactConvergenceStudy  impact_convergence;
    ReferenceModels         reference_models;
    ModalExpansionStudy     modal_expansion;
    RestitutionLaw          restitution_law;

  private:
    /// Everything but 'Task', 'Output directory' and 'Units'.
    void
    parse_physics(dealii::ParameterHandler &prm);
    /// The limits of a deformable collision partner (subsection Partner).
    void
    check_partner() const;
  };

  /**
   * Read @p filename into @p prm, its 'include FILE' lines replaced by
   * FILE (relative to the working directory, else to the including file). A
   * missing file, an include cycle, an unknown or misspelled entry or a
   * value that does not match its pattern throws an InputError with a
   * one-line message naming the file, the line and the entry.
   */
  void
  read_parameter_file(dealii::ParameterHandler &prm,
                      const std::string        &filename);
} // namespace DiskImpact
