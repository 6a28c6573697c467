#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace DiskImpact
{
  /// Throw if a PETSc or SLEPc call returned an error code.
  inline void
  check_petsc(const PetscErrorCode code, const char *call)
  {
    if (code != 0)
      throw std::runtime_error(std::string("PETSc/SLEPc call ") + call +
                               " failed with error code " +
                               std::to_string(code));
  }
} // namespace DiskImpact
