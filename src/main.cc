// diskimpact: finite-element analysis of an elastic or viscoelastic disk
// and its impact on a rigid wall. See README.md.

#include "base/input_error.h"
#include "base/run_error.h"
#include "run/parameters.h"
#include "tasks/task_runner.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cctype>
#include <iostream>
#include <new>
#include <sstream>
#include <string>

namespace
{
  /// @p text with every run of white space (line breaks too) one space.
  std::string
  one_line(const std::string &text)
  {
    std::string line;
    bool        space = false;
    for (const char c : text)
      if (std::isspace(static_cast<unsigned char>(c)))
        space = !line.empty();
      else
        {
          if (space)
            line += ' ';
          line += c;
          space = false;
        }
    return line;
  }

  void
  print_usage(std::ostream &out)
  {
    out << "usage: diskimpact FILE.prm\n"
           "       diskimpact --print-parameters [FILE.prm]\n"
           "       diskimpact --print-parameters-json\n"
           "Runs the task named in FILE.prm (also under mpirun -np N);\n"
           "--print-parameters writes every parameter with its default (or\n"
           "the value in FILE.prm) and its documentation;\n"
           "--print-parameters-json the same as JSON with the allowed values\n"
           "and the old names of renamed parameters (docs/reference/\n"
           "parameters.md is made from it by scripts/parameter_reference).\n";
  }

  /// Parse the command line and run; returns the exit code.
  int
  run(const int argc, char **argv, MPI_Comm communicator)
  {
    using namespace DiskImpact;
    const std::vector<std::string> args(argv + 1, argv + argc);
    const bool                     root =
      dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    // Every parameter in declaration order, in @p style, from rank 0.
    auto print = [root](const dealii::ParameterHandler             &prm,
                        const dealii::ParameterHandler::OutputStyle style) {
      if (root)
        prm.print_parameters(std::cout,
                             dealii::ParameterHandler::OutputStyle(
                               style |
                               dealii::ParameterHandler::KeepDeclarationOrder));
    };
    if (args.size() == 1 && args[0] == "--print-parameters-json")
      {
        dealii::ParameterHandler prm;
        Parameters::declare_parameters(prm);
        print(prm, dealii::ParameterHandler::JSON);
        return 0;
      }
    const bool print_only = !args.empty() && args[0] == "--print-parameters";
    if (args.empty() || args[0] == "--help" || args[0] == "-h" ||
        args.size() > (print_only ? 2u : 1u) ||
        (!print_only && args[0].rfind("-", 0) == 0))
      {
        if (root)
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
      for (const std::string &notice : read_parameter_file(prm, file))
        if (root)
          std::cerr << "diskimpact: note: " << notice << std::endl;
    Parameters parameters;
    try
      {
        parameters.parse_parameters(prm);
      }
    catch (const dealii::ExceptionBase &e)
      {
        // A value its pattern accepts but the conversion does not (e.g. a
        // number below the smallest double).
        std::ostringstream info;
        e.print_info(info);
        throw InputError("in parameter file '" + file + "': " + info.str());
      }

    if (root)
      for (const std::string &warning : parameters.warnings)
        std::cerr << "diskimpact: warning: " << warning << std::endl;

    if (print_only)
      {
        print(prm, dealii::ParameterHandler::PRM);
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
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const bool several_ranks =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
  // Errors are reported as one line on standard error. Input errors and run
  // errors arise on every rank alike (parsing and the checks of a run see
  // the same data on all ranks; failures of one rank's own work are shared
  // by share_failure()): rank 0 reports them and every rank returns 1.
  auto report = [rank](const std::string &what) {
    if (rank == 0)
      std::cerr << "diskimpact: error: " << one_line(what) << std::endl;
    return 1;
  };
  // Anything else arose on this rank alone, while the others may wait for
  // it in a collective call: report it and end all ranks.
  auto report_and_abort = [rank, several_ranks](const std::string &what) {
    std::cerr << "diskimpact: error"
              << (several_ranks ? " on MPI rank " + std::to_string(rank) : "")
              << ": " << one_line(what) << std::endl;
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
      return report(e.what());
    }
  catch (const DiskImpact::RunError &e)
    {
      return report(e.what());
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      return report_and_abort("internal error: " + info.str());
    }
  catch (const std::bad_alloc &)
    {
      return report_and_abort("out of memory");
    }
  catch (const std::exception &e)
    {
      return report_and_abort(e.what());
    }
}
