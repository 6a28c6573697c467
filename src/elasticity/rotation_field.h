#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

namespace DiskImpact
{
  /// The rigid rotation e_z x (x - c) about the centre @p c: the linear
  /// field whose interpolant is exact on the elements.
  template <int dim>
  class RotationField : public dealii::Function<dim>
  {
  public:
    explicit RotationField(const dealii::Point<dim> &center)
        : dealii::Function<dim>(dim)
        , center(center)
    {
    }

    double
    value(const dealii::Point<dim> &x,
          const unsigned int        component) const override
    {
      return component == 0 ? -(x[1] - center[1]) :
             component == 1 ? x[0] - center[0] :
                              0.;
    }

  private:
    const dealii::Point<dim> center;
  };
} // namespace DiskImpact
