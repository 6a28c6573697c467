#pragma once

#include <set>
#include <string>
#include <vector>

namespace DiskImpact
{
  class CsvTable;

  /**
   * An HDF5 result file of named groups holding 1-D double datasets (table
   * columns, DoF vectors) and scalar attributes (numbers, strings), built on
   * deal.II's HDF5 wrapper. h5py reads a column as f["group"]["name"].
   *
   * The file is written atomically: everything goes to FILENAME.tmp, which
   * finish() renames to FILENAME. A writer destroyed without finish() (e.g.
   * during stack unwinding) deletes FILENAME.tmp, so a reader never sees a
   * half-written file and a failed run leaves no FILENAME.
   *
   * Each call opens FILENAME.tmp, writes and closes it again, so no HDF5
   * object is alive between calls: deal.II (built with MPI) calls MPI_Abort
   * when an HDF5 object is destroyed while an exception propagates, even for
   * a serial file.
   *
   * The file is opened with HDF5's serial (POSIX) driver, which is not
   * collective even in the MPI build of HDF5: use this class on one process
   * only (e.g. MPI rank 0, with the data gathered there), never on several
   * ranks with the same file name.
   *
   * Group names: "/" is the file's root; any other name is a group directly
   * below it, created on first use. Each dataset or attribute name is
   * written once per group. Errors throw: std::invalid_argument for a
   * repeated or invalid name, std::logic_error for a write after finish(),
   * std::runtime_error for a failure of HDF5 or of the file system (in a
   * Debug build deal.II's own checks may stop the program first).
   */
  class Hdf5Output
  {
  public:
    /// Create FILENAME.tmp (truncating an old one); FILENAME is untouched.
    explicit Hdf5Output(const std::string &filename);

    /// Without finish(): delete FILENAME.tmp.
    ~Hdf5Output();

    Hdf5Output(const Hdf5Output &) = delete;
    Hdf5Output &
    operator=(const Hdf5Output &) = delete;

    /// One dataset per column in @p group; columns must have equal lengths.
    void
    write_table(const std::string                      &group,
                const std::vector<std::string>         &column_names,
                const std::vector<std::vector<double>> &columns);

    /// The columns of @p table, all numeric (empty cells become NaN).
    void
    write_table(const std::string &group, const CsvTable &table);

    /// One dataset @p name in @p group.
    void
    write_vector(const std::string         &group,
                 const std::string         &name,
                 const std::vector<double> &values);

    /// A scalar attribute of @p group.
    void
    set_attribute(const std::string &group,
                  const std::string &name,
                  double             value);

    /// A UTF-8 string attribute of @p group.
    void
    set_attribute(const std::string &group,
                  const std::string &name,
                  const std::string &value);

    /// Rename FILENAME.tmp to FILENAME; no writes after this.
    void
    finish();


  private:
    /// Record @p name in @p group as written; throws if it cannot be.
    void
    claim(const std::string &group, const std::string &name);

    /// Whether @p group has yet to be created (and mark it as created).
    bool
    is_new_group(const std::string &group);

    const std::string     filename;
    const std::string     temporary;
    std::set<std::string> created_groups;
    std::set<std::string> written;
    bool                  finished = false;
  };
} // namespace DiskImpact
