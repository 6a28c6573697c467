#pragma once

#include <deal.II/base/tensor.h>

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <vector>

namespace DiskImpact
{
  template <int dim>
  class ElasticityOperator;

  /**
   * The rigid motion of each body of a mesh that holds several (cells of
   * body i have material id i): its centre of mass along the impact
   * normal n, its mass, and its share of the kinetic and strain energy
   * (and of an elastic-plastic body's u . f_p).
   *
   * Body i's centre-of-mass component of a field x along n is
   * (M n_i) . x / (n_i . M n_i), n_i the uniform field n on body i's DoFs
   * and 0 elsewhere (the bodies share no DoF).
   */
  template <int dim>
  class BodyMotion
  {
  public:
    /// Collective.
    BodyMotion(const ElasticityOperator<dim> &op,
               const dealii::Tensor<1, dim>  &normal,
               unsigned int                   n_bodies);

    unsigned int
    n_bodies() const;
    /// n_i: n on body @p body's DoFs, 0 elsewhere.
    const dealii::PETScWrappers::MPI::Vector &
    normal_field(unsigned int body) const;
    /// n_i . M n_i: the mass of the computed domain of the body.
    double
    mass(unsigned int body) const;
    /// The centre-of-mass component of @p x along n. Collective.
    double
    center_of_mass(unsigned int                              body,
                   const dealii::PETScWrappers::MPI::Vector &x) const;
    /// x_i^T A x_i / 2 with x_i = x on the body's DoFs, 0 elsewhere, for
    /// A = M (kinetic energy) or K (strain energy); constrained entries
    /// ignored, as for the condensed matrices. Collective.
    double
    quadratic_form(unsigned int                                    body,
                   const dealii::PETScWrappers::MPI::SparseMatrix &matrix,
                   const dealii::PETScWrappers::MPI::Vector       &x) const;

    /// x_i . y with x_i = x on the body's DoFs, 0 elsewhere; constrained
    /// entries ignored. Collective.
    double
    dot(unsigned int                              body,
        const dealii::PETScWrappers::MPI::Vector &x,
        const dealii::PETScWrappers::MPI::Vector &y) const;

  private:
    const ElasticityOperator<dim>                  &op;
    std::vector<dealii::PETScWrappers::MPI::Vector> normals, indicators,
      momenta;
    std::vector<double>                        masses;
    mutable dealii::PETScWrappers::MPI::Vector work, product;
  };
} // namespace DiskImpact
