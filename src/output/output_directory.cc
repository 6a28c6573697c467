#include "output/output_directory.h"

#include "base/parameter_json.h"
#include "base/run_error.h"
#include "output/atomic_file.h"
#include "output/file_lock.h"

#include <algorithm>
#include <filesystem>
#include <fnmatch.h>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace DiskImpact
{
  OutputDirectory::OutputDirectory(const std::string &path,
                                   MPI_Comm           communicator)
      : path_name(path)
      , communicator(communicator)
  {
    on_root(communicator, [&]() {
      std::error_code error;
      std::filesystem::create_directories(path_name, error);
      if (error)
        throw std::runtime_error("cannot create output directory '" +
                                 path_name + "': " + error.message());
      const std::string lock_file = path_name + "/.diskimpact.lock";
      bool              held      = false;
      lock                        = std::make_unique<FileLock>(lock_file, held);
      if (!held)
        {
          lock.reset();
          std::string holder;
          std::getline(std::ifstream(lock_file), holder);
          throw std::runtime_error(
            "output directory '" + path_name +
            "' is in use by another diskimpact run" +
            (holder.empty() ? "" : " (process " + holder + ")") +
            "; wait for it to end or choose another 'Output directory'");
        }
      // The holder's process id, for the message above.
      std::ofstream(lock_file) << ::getpid() << '\n';
    });
  }

  OutputDirectory::~OutputDirectory() = default;

  const std::string &
  OutputDirectory::path() const
  {
    return path_name;
  }

  void
  OutputDirectory::remove_results(const std::vector<std::string> &patterns,
                                  const std::vector<std::string> &keep) const
  {
    on_root(communicator, [&]() {
      for (const auto &entry : std::filesystem::directory_iterator(path_name))
        {
          const std::string name = entry.path().filename().string();
          if (!entry.is_regular_file() ||
              std::find(keep.begin(), keep.end(), name) != keep.end())
            continue;
          const bool result =
            fnmatch("*.tmp", name.c_str(), 0) == 0 ||
            std::any_of(patterns.begin(),
                        patterns.end(),
                        [&](const std::string &pattern) {
                          return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
                        });
          std::error_code error;
          if (result && !std::filesystem::remove(entry.path(), error) && error)
            throw std::runtime_error("cannot remove the earlier result " +
                                     entry.path().string() + ": " +
                                     error.message());
        }
    });
  }

  void
  OutputDirectory::write_parameters(const dealii::ParameterHandler &prm) const
  {
    using dealii::ParameterHandler;
    on_root(communicator, [&]() {
      write_atomically(
        path_name + "/used_parameters.prm", [&](std::ostream &out) {
          prm.print_parameters(out,
                               ParameterHandler::OutputStyle(
                                 ParameterHandler::PRM |
                                 ParameterHandler::KeepDeclarationOrder));
        });
      write_atomically(path_name + "/used_parameters.json",
                       parameters_as_json(prm, ParameterHandler::JSON));
    });
  }
} // namespace DiskImpact
