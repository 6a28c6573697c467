#include "output/vtu_record.h"

#include "base/run_error.h"
#include "output/atomic_file.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

namespace DiskImpact
{
  using namespace dealii;

  template <int dim, int spacedim>
  std::string
  write_vtu_record(const DataOutInterface<dim, spacedim> &data,
                   const std::string                     &directory,
                   const std::string                     &basename,
                   const unsigned int                     index,
                   MPI_Comm                               communicator)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank_digits =
      Utilities::needed_digits(std::max(0, static_cast<int>(n_ranks) - 1));
    const std::string stem =
      basename + "_" + Utilities::int_to_string(index, 4) + ".";
    auto piece = [&](const unsigned int r) {
      return stem + Utilities::int_to_string(r, rank_digits) + ".vtu";
    };
    // Each rank's piece, then the record, once every piece is whole.
    collectively(communicator, [&]() {
      write_atomically(directory + "/" + piece(rank),
                       [&](std::ostream &out) { data.write_vtu(out); });
    });
    const std::string record = stem.substr(0, stem.size() - 1) + ".pvtu";
    on_root(communicator, [&]() {
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < n_ranks; ++r)
        pieces.push_back(piece(r));
      write_atomically(directory + "/" + record, [&](std::ostream &out) {
        data.write_pvtu_record(out, pieces);
      });
    });
    return record;
  }

  template <int dim, int spacedim>
  void
  scale_patches(std::vector<DataOutBase::Patch<dim, spacedim>>   &patches,
                const std::vector<std::string>                   &names,
                const double                                      length,
                const std::function<double(const std::string &)> &factor)
  {
    std::vector<double> factors;
    for (const std::string &name : names)
      factors.push_back(factor(name));
    for (auto &patch : patches)
      {
        for (auto &vertex : patch.vertices)
          vertex *= length;
        const unsigned int n_rows = patch.data.size(0);
        for (unsigned int row = 0; row < n_rows; ++row)
          {
            // Curved patches keep their points' coordinates in the last
            // spacedim rows.
            const double scale = row < factors.size() ?
                                   factors[row] :
                                   (patch.points_are_available ? length : 1.);
            for (unsigned int point = 0; point < patch.data.size(1); ++point)
              patch.data(row, point) *= scale;
          }
      }
  }

  template std::string
  write_vtu_record(const DataOutInterface<2, 2> &,
                   const std::string &,
                   const std::string &,
                   unsigned int,
                   MPI_Comm);
  template std::string
  write_vtu_record(const DataOutInterface<3, 3> &,
                   const std::string &,
                   const std::string &,
                   unsigned int,
                   MPI_Comm);
  template std::string
  write_vtu_record(const DataOutInterface<2, 3> &,
                   const std::string &,
                   const std::string &,
                   unsigned int,
                   MPI_Comm);
  template void
  scale_patches(std::vector<DataOutBase::Patch<2, 2>> &,
                const std::vector<std::string> &,
                double,
                const std::function<double(const std::string &)> &);
  template void
  scale_patches(std::vector<DataOutBase::Patch<3, 3>> &,
                const std::vector<std::string> &,
                double,
                const std::function<double(const std::string &)> &);
} // namespace DiskImpact
