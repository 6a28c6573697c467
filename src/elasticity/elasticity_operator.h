#pragma once

#include "elasticity/discrete_operator.h"
#include "elasticity/section.h"
#include "material/constitutive_law.h"
#include "material/material.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor_function.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <memory>
#include <vector>

namespace DiskImpact
{
  class BodyGeometry;

  /// Subsection "Finite element": the polynomial degree of the elements.
  struct FiniteElementParameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    unsigned int degree = 2;
  };

  /**
   * The discrete linear elasticity operator of the body: vector Q_k elements
   * with a degree-k boundary mapping, the constraints (hanging nodes, the
   * symmetry condition u_y = 0 of a half disk or on a sphere's axis), and
   * the mass and stiffness matrices as distributed PETSc matrices, planar or
   * axisymmetric (Section).
   */
  template <int dim>
  class ElasticityOperator : public DiscreteOperator<dim>
  {
  public:
    explicit ElasticityOperator(unsigned int degree);

    /// Distribute DoFs on @p triangulation, build constraints and matrices
    /// (with @p with_tangent also a matrix of K's pattern for Newton). The
    /// x-displacement is held at zero at the mesh vertices @p axial_pins
    /// (a free body's translation along the impact axis, removed for a
    /// static solve).
    void
    setup(
      const dealii::parallel::distributed::Triangulation<dim> &triangulation,
      const BodyGeometry                                      &geometry,
      bool                                   with_tangent = false,
      const std::vector<dealii::Point<dim>> &axial_pins   = {});

    /**
     * Mass redistribution (Khenous, Laborde & Renard, Eur. J. Mech. A/Solids
     * 27, 2008): the DoFs on the curved-edge faces within @p radius of
     * @p point carry no inertia. In each cell the mass form is that of Pi u,
     * where Pi gives each such DoF the value of the nearest cell DoF of the
     * same component off that part of the edge. The hanging nodes whose
     * constraints involve those DoFs are moved the same way (their mass
     * would otherwise reach them through the constraints). Pi keeps
     * constants, so the total mass and the momentum of a uniform motion
     * are those of the consistent mass matrix. Call between setup() and
     * assemble().
     */
    void
    set_massless_edge_zone(const dealii::Point<dim> &point, double radius);
    /// The number of DoFs without inertia (set_massless_edge_zone()).
    unsigned int
    n_massless_dofs() const;
    /// The DoFs without inertia, sorted, the same list on every rank.
    /// Collective.
    std::vector<dealii::types::global_dof_index>
    massless_dof_list() const;
    /// The block K(dofs, dofs) of the stiffness matrix for a sorted list
    /// @p dofs, the same on every rank. Collective.
    dealii::FullMatrix<double>
    stiffness_block(
      const std::vector<dealii::types::global_dof_index> &dofs) const;

    /// Assemble M (rho u.v) and K (eps(u) : C : eps(v)), and for a viscous
    /// material the damping matrix (eps(u) : D : eps(v), Kelvin-Voigt);
    /// each over the body's volume (Section), with the hoop strain of an
    /// axisymmetric body.
    void
    assemble(const Material &material);
    /// The same with the material of each cell: materials[material_id]
    /// (a collision partner's cells have material id 1).
    void
    assemble(const std::vector<Material> &materials);
    /// Whether assemble() built a damping matrix.
    bool
    has_damping() const;

    /// The vector m with m . x = x^T M y for every field x (the condensed
    /// M, constrained entries of x and y ignored): M y with the constrained
    /// entries of y and of the result zeroed. With y a uniform translation,
    /// m . v is the momentum of the velocity field v along it.
    dealii::PETScWrappers::MPI::Vector
    mass_functional(const dealii::PETScWrappers::MPI::Vector &y) const;

    /// f_i = int b . v_i dV for a uniform body force @p force_per_area (per
    /// volume for a sphere), on the cells of material id @p body (all cells
    /// if invalid_material_id).
    void
    assemble_body_force(const dealii::Tensor<1, dim>       &force_per_area,
                        dealii::PETScWrappers::MPI::Vector &f,
                        dealii::types::material_id          body =
                          dealii::numbers::invalid_material_id) const;

    /// The same for a body force that varies in space.
    void
    assemble_body_force(const dealii::TensorFunction<1, dim> &force_per_area,
                        dealii::PETScWrappers::MPI::Vector   &f,
                        dealii::types::material_id            body =
                          dealii::numbers::invalid_material_id) const;

    /// The volume (area for a disk of unit thickness) of the cells of
    /// material id @p body (all if invalid_material_id), with the quadrature
    /// of assemble_body_force().
    double
    volume(dealii::types::material_id body =
             dealii::numbers::invalid_material_id) const;

    /// Volume average of the displacement over the cells of material id
    /// @p body (all if invalid_material_id): the centre of mass's
    /// displacement for a uniform density (on a sphere along the axis only).
    dealii::Tensor<1, dim>
    mean_displacement(const dealii::PETScWrappers::MPI::Vector &ghosted_u,
                      dealii::types::material_id                body =
                        dealii::numbers::invalid_material_id) const;

    /// The displacement at a vertex of the mesh, seen from the cells of
    /// material id @p body (all if invalid_material_id): two bodies that
    /// touch have a vertex each at the contact point.
    dealii::Tensor<1, dim>
    vertex_displacement(const dealii::PETScWrappers::MPI::Vector &ghosted_u,
                        const dealii::Point<dim>                 &vertex,
                        dealii::types::material_id                body =
                          dealii::numbers::invalid_material_id) const;

    /// The Newton tangent, reset to K (setup() with with_tangent).
    dealii::PETScWrappers::MPI::SparseMatrix &
    tangent_reset_to_stiffness();
    /// The Newton tangent as last assembled.
    const dealii::PETScWrappers::MPI::SparseMatrix &
    tangent_matrix() const;

    /// Planar or axisymmetric (set by setup() from the geometry).
    const Section<dim> &
    get_section() const;
    /// The constitutive law of each body (by material id), as assemble()
    /// made them.
    const ConstitutiveLaw<dim> &
    constitutive_law(unsigned int body = 0) const;
    /// The laws' states at the quadrature points of the locally owned
    /// cells (the order of assemble()'s QGauss(degree + 1)).
    QuadraturePointStates<dim> &
    quadrature_point_states();
    const dealii::PETScWrappers::MPI::SparseMatrix &
    damping_matrix() const;

  private:
    using DiscreteOperator<dim>::fe_degree;
    using DiscreteOperator<dim>::mapping;
    using DiscreteOperator<dim>::dof_handler;
    using DiscreteOperator<dim>::owned_dofs;
    using DiscreteOperator<dim>::relevant_dofs;
    using DiscreteOperator<dim>::constraints;
    using DiscreteOperator<dim>::mass;
    using DiscreteOperator<dim>::stiffness;

    /// Constrain the x-displacement to zero at the vertices @p pins.
    void
    pin_axial_displacement(const std::vector<dealii::Point<dim>> &pins);

    Section<dim> section;

    std::unique_ptr<dealii::FESystem<dim>> fe;
    /// DoFs without inertia (mass redistribution), size n_dofs.
    dealii::IndexSet massless_dofs;
    /// The DoFs whose mass moves in the cell mass form: massless_dofs and
    /// every constrained DoF whose constraint involves one of them (a
    /// hanging node's mass would otherwise reach them through it).
    dealii::IndexSet redistributed_dofs;

    /// The cell mass matrix of Pi u (set_massless_edge_zone()).
    void
    redistribute_cell_mass(
      const std::vector<dealii::types::global_dof_index> &dof_indices,
      dealii::FullMatrix<double>                         &cell_mass) const;

    dealii::PETScWrappers::MPI::SparseMatrix tangent;
    dealii::PETScWrappers::MPI::SparseMatrix damping;
    bool                                     with_damping = false;
    /// Each body's law, and the laws' states at the quadrature points.
    std::vector<std::unique_ptr<ConstitutiveLaw<dim>>> laws;
    QuadraturePointStates<dim>                         point_states;
  };
} // namespace DiskImpact
