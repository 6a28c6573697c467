// Catch2 runner with MPI, PETSc and SLEPc initialised for the FE checks.
#define CATCH_CONFIG_RUNNER
#include <deal.II/base/mpi.h>

#include <catch2/catch.hpp>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return Catch::Session().run(argc, argv);
}
