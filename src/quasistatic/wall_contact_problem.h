#pragma once

#include "contact/contact_operator.h"
#include "elasticity/elasticity_operator.h"
#include "elasticity/plastic_strain_field.h"
#include "reference/hertz_first_yield.h"
#include "reference/wall_contact_theory.h"

#include <deal.II/distributed/tria.h>

#include <deal.II/lac/petsc_vector.h>

#include <mpi.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace DiskImpact
{
  struct Parameters;
  struct ContactLawPoint;

  /// Where Hertz's half-space first yields: the sphere on its axis, the
  /// disk with its out-of-plane stress (nu tr sigma in plane strain, 0 in
  /// plane stress).
  Reference::FirstYield
  hertz_first_yield(const Parameters &parameters);

  /**
   * A half disk or a sphere pressed on the wall by a uniform body force of
   * total P (Gerl & Zippelius 1999, section 5), in two dimensions (the
   * plane models, the sphere's meridian) or three (the quarter of a disk
   * of finite thickness, the quarter sphere), solved by Newton's method
   * with a line search on the penalty contact problem: the state of task
   * 'quasistatic contact' at one load, or one step of a loading path.
   *
   * An elastic-plastic body (enable_plasticity()) carries its plastic
   * strains from one load to the next: the internal force is K u - f_p
   * (PlasticStrainField), Newton's tangent adds the return mapping's
   * consistent tangent, and accept() ends a load step. At load 0 the body
   * is off the wall: the contact law is left out and its point nearest
   * the wall held along the wall's normal, which the body force no longer
   * does (the force f_p of the residual stresses is self-equilibrated, so
   * the hold carries no force).
   */
  template <int dim>
  class WallContactProblem
  {
  public:
    /// The mesh graded for @p mesh_load (QuasistaticContact::create_mesh()),
    /// the body force of @p load.
    WallContactProblem(const Parameters &parameters,
                       double            load,
                       double            mesh_load,
                       MPI_Comm          communicator);
    ~WallContactProblem();

    /// Plastic strains at the quadrature points (Material 'Yield stress').
    void
    enable_plasticity();
    /// The body force of @p load (0: off the wall, see the class).
    void
    set_load(double load);
    double
    get_load() const;

    /// Set the displacement to a rigid translation toward the wall by
    /// @p compression (times R).
    void
    translate(double compression);
    /// Newton from the current displacement to |residual| <= @p tolerance
    /// times the force of the mesh's load; returns the iterations used.
    unsigned int
    solve(double tolerance, unsigned int max_iterations);
    /// An elastic-plastic body: the converged state's plastic strains
    /// become the start of the next load; returns the load step's plastic
    /// work (whole body).
    double
    accept();

    /// The contact law's point at the current load (an elastic body; in
    /// 3D without the first yield's stress).
    ContactLawPoint
    results() const;
    /// Approach of the centre of mass and shortening of the axial diameter
    /// (both over R; in 3D the diameter in the plane z = 0), as in
    /// results().
    std::pair<double, double>
    approach() const;
    const dealii::PETScWrappers::MPI::Vector &
    displacement() const;
    /// The body force's vector f (of the current load).
    const dealii::PETScWrappers::MPI::Vector &
    body_force_vector() const;
    /// The contact's term c(u) in the residual K u - f_p - f + c(u) (and
    /// at load 0 the hold's), at the current displacement.
    dealii::PETScWrappers::MPI::Vector
    support_force_vector() const;
    /// The wall's contact state at the current displacement.
    ContactState
    contact_state() const;
    /// u.(K u)/2 - u.f_p + int eps_p : C : eps_p dV / 2 (the residual
    /// stresses' energy with it), of the whole body.
    double
    elastic_energy() const;
    /// The largest equivalent plastic strain (0 for an elastic body).
    double
    largest_plastic_strain() const;
    /// Force P of a dimensionless load (whole body).
    double
    force(double load) const;
    unsigned int
    n_dofs() const;
    /// The fraction of the body the mesh holds (1/2 for a half disk).
    double
    domain_share() const;

    std::vector<std::pair<double, double>>
    pressure_profile() const;
    /// P / R (disk) or P / R^2 (sphere).
    double
    pressure_unit() const;
    /// The deformed state (with stresses, or an elastic-plastic body's
    /// plastic strain and von Mises stress per cell); returns the .pvtu's
    /// name.
    std::string
    write_state(const std::string &directory, unsigned int index) const;

  private:
    /// R(u) = K u - f_p - f + contact, constrained entries zero; tangent if
    /// asked.
    ContactState
    residual(const dealii::PETScWrappers::MPI::Vector &u,
             dealii::PETScWrappers::MPI::Vector       &r,
             bool                                      with_tangent);
    /// The support's term into @p r and @p tangent (both compressed): the
    /// contact, or at load 0 the spring that holds the point nearest the
    /// wall (its stiffness that of K's diagonal there).
    ContactState
    add_support(const dealii::PETScWrappers::MPI::Vector &u,
                dealii::PETScWrappers::MPI::Vector       &r,
                dealii::PETScWrappers::MPI::SparseMatrix *tangent) const;

    const Parameters                                   &parameters;
    double                                              load;
    const std::unique_ptr<Reference::WallContactTheory> theory;
    MPI_Comm                                            communicator;
    dealii::parallel::distributed::Triangulation<dim>   triangulation;
    ElasticityOperator<dim>                             op;
    RigidWall<dim>                                      wall;
    std::unique_ptr<ContactOperator<dim>>               contact;
    std::unique_ptr<PlasticStrainField<dim>>            plasticity;
    dealii::PETScWrappers::MPI::Vector                  body_force;
    dealii::PETScWrappers::MPI::Vector                  plastic_force;
    dealii::PETScWrappers::MPI::Vector                  solution;
    /// The norm of the body force of the mesh's load: Newton's scale.
    double                                              force_scale = 0.;
    /// The DoF of the wall-normal displacement at the point nearest the
    /// wall, if this rank owns it.
    dealii::types::global_dof_index                     hold_dof;
    bool                                                owns_hold = false;
    unsigned int                                        iterations = 0;
    double                                              h_contact  = 0.;
  };
} // namespace DiskImpact
