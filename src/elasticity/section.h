#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace DiskImpact
{
  /**
   * How the two-dimensional section stands for the three-dimensional body
   * in the weak form.
   *
   * - Planar (disk): a slab of unit thickness, dV = dA, no out-of-plane
   *   strain beyond what the plane model builds into the in-plane constants.
   * - Axisymmetric (sphere): the meridian of a body of revolution about the
   *   axis y = 0, with r = y: dV = 2 pi r dA, dS = 2 pi r ds, and the hoop
   *   strain eps_theta = u_r / r = u_y / y beside the meridian's strains.
   *   Masses, forces, energies and momenta are then those of the whole 3D
   *   body.
   * - Solid (dim = 3): the body itself, dV = dA = 1 per unit volume.
   */
  template <int dim>
  class Section
  {
  public:
    explicit Section(const bool axisymmetric = false)
        : axisymmetric(axisymmetric)
    {
      Assert(dim == 2 || !axisymmetric,
             dealii::ExcMessage("an axisymmetric section is two-dimensional"));
    }

    bool
    is_axisymmetric() const
    {
      return axisymmetric;
    }

    /// dV / dA (or dS / ds on the boundary) at @p point.
    double
    measure(const dealii::Point<dim> &point) const
    {
      return axisymmetric ? 2. * M_PI * point[1] : 1.;
    }

    /// The hoop strain u_r / r of displacement @p u at @p point (0 planar).
    /// Quadrature points never lie on the axis.
    double
    hoop_strain(const dealii::Tensor<1, dim> &u,
                const dealii::Point<dim>     &point) const
    {
      return axisymmetric ? u[1] / point[1] : 0.;
    }

  private:
    bool axisymmetric;
  };

  /// The three-dimensional tensor of a section's in-plane part @p in_plane
  /// and out-of-plane part @p out_of_plane (zz: the hoop component of an
  /// axisymmetric body; the plane models' sigma_zz or eps_zz).
  inline dealii::SymmetricTensor<2, 3>
  three_dimensional(const dealii::SymmetricTensor<2, 2> &in_plane,
                    const double                         out_of_plane)
  {
    dealii::SymmetricTensor<2, 3> full;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        full[i][j] = in_plane[i][j];
    full[2][2] = out_of_plane;
    return full;
  }

  /// A solid's tensor is already three-dimensional.
  inline dealii::SymmetricTensor<2, 3>
  three_dimensional(const dealii::SymmetricTensor<2, 3> &tensor, double)
  {
    return tensor;
  }
} // namespace DiskImpact
