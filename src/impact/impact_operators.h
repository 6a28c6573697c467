#pragma once

#include "contact/contact.h"
#include "dynamics/factorization.h"
#include "elasticity/constraint_map.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/interleaved_mass.h"
#include "material/material.h"

#include <deal.II/distributed/tria.h>

#include <mpi.h>

#include <memory>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /// ImpactOperators of either dimension, as the runs that share them hold
  /// them (ImpactSimulation casts to its own dimension's).
  struct ImpactOperatorsBase
  {
    virtual ~ImpactOperatorsBase() = default;

    /// Each body's material, by material id.
    static std::vector<Material>
    materials(const Parameters &parameters);
  };

  /// The operators of @p parameters in the geometry's dimension.
  std::shared_ptr<ImpactOperatorsBase>
  make_impact_operators(const Parameters &parameters, MPI_Comm communicator);

  /**
   * The part of an impact's set-up that does not depend on the time step:
   * the mesh graded toward the contact, the assembled mass, stiffness (and
   * damping) operators with their massless edge zone, the constraints as a
   * matrix, the wall law and the bound on the contact candidates' gap. The
   * runs of a convergence study that differ only in their time step share
   * one (docs/theory/impact-method.md, "The condensed contact solve"); the
   * time stepping only reads it, besides the effective matrix and its
   * factorization, which each run's time step makes afresh.
   */
  template <int dim>
  struct ImpactOperators : ImpactOperatorsBase
  {
    /// Build and assemble on @p communicator. Collective.
    ImpactOperators(const Parameters &parameters, MPI_Comm communicator);

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    ElasticityOperator<dim>                           op;
    /// op's constraints as a matrix, for the time loop.
    std::unique_ptr<ConstraintMap> constraint_map;
    /// The product with op's mass matrix, for the time loop.
    std::unique_ptr<InterleavedMass> mass_product;
    /// The wall's law, scaled by the smallest edge face (null: the exact
    /// constraint).
    std::shared_ptr<const ContactLaw> law;
    /// The candidates for contact: the edge points whose undeformed gap is
    /// below this bound.
    double candidate_bound = 0.;
    /// The effective matrix's factorization, once there is one: a run with
    /// another time step refactorizes it, keeping its pattern's part. So
    /// the runs that share these operators run one after the other.
    std::shared_ptr<Factorization> factorization;
  };
} // namespace DiskImpact
