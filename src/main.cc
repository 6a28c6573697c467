// diskimpact: finite-element analysis of an elastic or viscoelastic disk
// and its impact on a rigid wall. See README.md.

#include "base/input_error.h"
#include "base/parameters.h"
#include "tasks/task_runner.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <string>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "usage: diskimpact FILE.prm\n"
           "       diskimpact --print-parameters [FILE.prm]\n"
           "Runs the task named in FILE.prm (also under mpirun -np N);\n"
           "--print-parameters writes every parameter with its default (or\n"
           "the value in FILE.prm) and its documentation.\n";
  }

  /// Parse the command line and run; returns the exit code.
  int
  run(const int argc, char **argv, MPI_Comm communicator)
  {
    using namespace DiskImpact;
    const std::vector<std::string> args(argv + 1, argv + argc);
    const bool print_only = !args.empty() && args[0] == "--print-parameters";
    if (args.empty() || args[0] == "--help" || args[0] == "-h" ||
        args.size() > (print_only ? 2u : 1u) ||
        (!print_only && args[0].rfind("-", 0) == 0))
      {
        if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
          print_usage(args.empty() ? std::cerr : std::cout);
        return args.empty() || args[0].rfind("-", 0) != 0 ||
                   (args[0] != "--help" && args[0] != "-h") ?
                 2 :
                 0;
      }

    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    const std::string file =
      print_only ? (args.size() == 2 ? args[1] : "") : args[0];
    if (!file.empty())
      read_parameter_file(prm, file);
    Parameters parameters;
    parameters.parse_parameters(prm);

    if (print_only)
      {
        if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
          prm.print_parameters(
            std::cout,
            dealii::ParameterHandler::OutputStyle(
              dealii::ParameterHandler::PRM |
              dealii::ParameterHandler::KeepDeclarationOrder));
        return 0;
      }
    run_task(parameters, prm, communicator);
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               is_root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const bool several_ranks =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
  // Errors are reported as one line on standard error. Input errors arise
  // on every rank alike (rank 0 reports them); an error during a run may
  // arise on one rank alone while the others wait for it in a collective
  // call: that rank reports it and aborts all ranks.
  auto report = [is_root](const std::string &kind, const std::string &what) {
    if (is_root)
      std::cerr << "diskimpact: " << kind << what << std::endl;
    return 1;
  };
  auto report_and_abort = [several_ranks](const std::string &kind,
                                          const std::string &what) {
    std::cerr << "diskimpact: " << kind << what << std::endl;
    if (several_ranks)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  };
  try
    {
      return run(argc, argv, MPI_COMM_WORLD);
    }
  catch (const DiskImpact::InputError &e)
    {
      return report("error: ", e.what());
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      return report_and_abort("internal error: ", info.str());
    }
  catch (const std::exception &e)
    {
      return report_and_abort("error: ", e.what());
    }
}
