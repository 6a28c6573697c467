#pragma once

#include <deal.II/lac/petsc_vector.h>

#include <utility>

namespace DiskImpact
{
  /**
   * A distributed PETSc vector of the time loop's state, whose exchange()
   * trades storage with another of the same layout at no cost: deal.II's
   * swap() copies both vectors' entries (PETSc's VecSwap), which the time
   * loop did six times a step. For vectors without ghost entries.
   */
  class StateVector : public dealii::PETScWrappers::MPI::Vector
  {
  public:
    using dealii::PETScWrappers::MPI::Vector::Vector;

    StateVector &
    operator=(const dealii::PETScWrappers::MPI::Vector &v)
    {
      dealii::PETScWrappers::MPI::Vector::operator=(v);
      return *this;
    }

    /// Trade storage with @p other (same layout, no ghosts).
    void
    exchange(StateVector &other) noexcept
    {
      std::swap(vector, other.vector);
    }
  };
} // namespace DiskImpact
