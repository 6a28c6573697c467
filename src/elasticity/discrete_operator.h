#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <memory>

namespace DiskImpact
{
  /**
   * What the body's discrete operators share: Q_k elements on a
   * distributed mesh with a degree-k boundary mapping, the locally owned
   * and relevant DoFs, the constraints, and the mass and stiffness
   * matrices as distributed PETSc matrices. ElasticityOperator and
   * TorsionOperator add their fields, constraints and weak forms.
   */
  template <int dim>
  class DiscreteOperator
  {
  public:
    explicit DiscreteOperator(unsigned int degree);

    unsigned int
    degree() const;

    /**
     * Make constrained DoFs harmless for the eigenproblem: they are decoupled
     * rows with K_ii / M_ii set to @p eigenvalue, far above the spectrum of
     * interest (deal.II step-36 discusses these spurious eigenvalues).
     */
    void
    move_constrained_eigenvalues(double eigenvalue);

    const dealii::DoFHandler<dim> &
    get_dof_handler() const;
    const dealii::MappingQ<dim> &
    get_mapping() const;
    const dealii::AffineConstraints<double> &
    get_constraints() const;
    const dealii::IndexSet &
    locally_owned_dofs() const;
    const dealii::IndexSet &
    locally_relevant_dofs() const;
    const dealii::PETScWrappers::MPI::SparseMatrix &
    mass_matrix() const;
    const dealii::PETScWrappers::MPI::SparseMatrix &
    stiffness_matrix() const;

    /// A distributed vector without ghosts.
    dealii::PETScWrappers::MPI::Vector
    create_vector() const;
    /// A ghosted copy of @p vector (for evaluation on locally owned cells).
    dealii::PETScWrappers::MPI::Vector
    create_ghosted(const dealii::PETScWrappers::MPI::Vector &vector) const;

  protected:
    /// Distribute the DoFs of @p fe on @p triangulation in a
    /// bandwidth-reducing order (the mat-vec products of the eigensolver
    /// and the time integrator run through memory in order), set up the
    /// mapping and the owned and relevant DoFs.
    void
    distribute_dofs(
      const dealii::parallel::distributed::Triangulation<dim> &triangulation,
      const dealii::FiniteElement<dim>                        &fe);

    /**
     * In 3D: the mapping replaced by the positions of the element's own
     * nodes with the hanging-node constraints @p hanging applied. A refined
     * cell places its nodes on the manifold, its coarser neighbour's face
     * interpolates them, and the two disagree on curved faces; with the
     * constrained positions they agree, so every linear field (a rigid
     * rotation) is a constrained field of the elements, and the stiffness
     * conserves angular momentum exactly. In 2D hanging nodes lie on
     * straight interior edges, where the two agree already.
     */
    void
    conform_mapping_to_constraints(
      const dealii::AffineConstraints<double> &hanging);

    const unsigned int                       fe_degree;
    std::unique_ptr<dealii::MappingQ<dim>>   mapping;
    dealii::DoFHandler<dim>                  dof_handler;
    dealii::IndexSet                         owned_dofs;
    dealii::IndexSet                         relevant_dofs;
    dealii::AffineConstraints<double>        constraints;
    dealii::PETScWrappers::MPI::SparseMatrix mass;
    dealii::PETScWrappers::MPI::SparseMatrix stiffness;
  };
} // namespace DiskImpact
