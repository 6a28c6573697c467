#pragma once

#include <deal.II/base/data_out_base.h>

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * Write @p data as DIRECTORY/BASENAME_NNNN.R.vtu, one file per MPI rank R,
   * and the record DIRECTORY/BASENAME_NNNN.pvtu that ParaView opens (NNNN
   * = @p index), as deal.II's write_vtu_with_pvtu_record() names them, but
   * each file whole or not at all (write_atomically()): a full disk gives
   * one error line naming the file, on every rank (a RunError), and leaves
   * no truncated .vtu and no .pvtu of this index. Collective; returns the
   * .pvtu's name relative to @p directory.
   */
  template <int dim, int spacedim>
  std::string
  write_vtu_record(const dealii::DataOutInterface<dim, spacedim> &data,
                   const std::string                             &directory,
                   const std::string                             &basename,
                   unsigned int                                   index,
                   MPI_Comm                                       communicator);

  /**
   * Multiply each field of @p patches by @p factor of its name (@p names:
   * one per data row, in the order of DataOut's dataset names), and the
   * coordinates (the vertices, and the points of curved patches) by
   * @p length.
   */
  template <int dim, int spacedim>
  void
  scale_patches(std::vector<dealii::DataOutBase::Patch<dim, spacedim>> &patches,
                const std::vector<std::string>                         &names,
                double                                                  length,
                const std::function<double(const std::string &)>       &factor);
} // namespace DiskImpact
