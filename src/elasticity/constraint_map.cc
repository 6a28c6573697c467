#include "elasticity/constraint_map.h"

#include "base/petsc_check.h"

#include <deal.II/lac/dynamic_sparsity_pattern.h>

namespace DiskImpact
{
  using namespace dealii;

  ConstraintMap::ConstraintMap(const AffineConstraints<double> &constraints,
                               const IndexSet                  &locally_owned,
                               MPI_Comm                         communicator)
      : mask(locally_owned, communicator)
      , inhomogeneity(locally_owned, communicator)
      , mapped(locally_owned, communicator)
  {
    const auto             n = locally_owned.size();
    DynamicSparsityPattern pattern(n, n, locally_owned);
    for (const auto i : locally_owned)
      {
        if (const auto *entries = constraints.get_constraint_entries(i))
          {
            for (const auto &[j, weight] : *entries)
              pattern.add(i, j);
          }
        else
          pattern.add(i, i);
      }
    map.reinit(locally_owned, locally_owned, pattern, communicator);
    for (const auto i : locally_owned)
      if (const auto *entries = constraints.get_constraint_entries(i))
        {
          for (const auto &[j, weight] : *entries)
            map.set(i, j, weight);
          inhomogeneity(i) = constraints.get_inhomogeneity(i);
        }
      else
        {
          map.set(i, i, 1.);
          mask(i) = 1.;
        }
    map.compress(VectorOperation::insert);
    mask.compress(VectorOperation::insert);
    inhomogeneity.compress(VectorOperation::insert);
  }

  void
  ConstraintMap::distribute(PETScWrappers::MPI::Vector &x) const
  {
    check_petsc(MatMultAdd(map, x, inhomogeneity, mapped), "MatMultAdd");
    check_petsc(VecCopy(mapped, x), "VecCopy");
  }

  void
  ConstraintMap::set_zero(PETScWrappers::MPI::Vector &x) const
  {
    check_petsc(VecPointwiseMult(x, x, mask), "VecPointwiseMult");
  }

  void
  ConstraintMap::zeroed(const PETScWrappers::MPI::Vector &x,
                        PETScWrappers::MPI::Vector       &result) const
  {
    check_petsc(VecPointwiseMult(result, x, mask), "VecPointwiseMult");
  }
} // namespace DiskImpact
