#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
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
} // namespace DiskImpact
