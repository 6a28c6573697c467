#pragma once

#include <hdf5.h>
#include <set>
#include <string>
#include <vector>

namespace DiskImpact
{
  class CsvTable;
  class UnitSystem;

  /**
   * An HDF5 result file of named groups holding 1-D double datasets (table
   * columns, DoF vectors) and scalar attributes (numbers, strings). h5py
   * reads a column as f["group"]["name"].
   *
   * The file is built in memory (HDF5's core driver) and written to disk in
   * one piece by finish(), through write_atomically(): FILENAME appears
   * whole or not at all, and a full disk is one line of error, as for every
   * other result file. A writer destroyed without finish() writes nothing.
   * HDF5's C interface is used directly: deal.II's wrapper checks HDF5's
   * return codes only in Debug builds and aborts MPI when its objects are
   * destroyed while an exception propagates.
   *
   * Use it on one process only (e.g. MPI rank 0, with the data gathered
   * there). Group names: "/" is the file's root; any other name is a group
   * directly below it, created on first use. Each dataset or attribute
   * name is written once per group. Errors throw: std::invalid_argument for
   * a repeated or invalid name, std::logic_error for a write after
   * finish(), std::runtime_error for a failure of HDF5 or of the file
   * system.
   */
  class Hdf5Output
  {
  public:
    /// An empty file in memory; throws if @p filename's directory does not
    /// exist.
    explicit Hdf5Output(const std::string &filename);

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

    /**
     * For an SI run (@p units), root attributes with the SI values of the
     * units the file's numbers are in: length_unit_m (R), time_unit_s
     * (R/c), speed_unit_m_per_s (c), force_unit with force_unit_name ("N"
     * for a sphere, "N/m" for a disk), energy_unit (force times length, "J"
     * or "J/m"). Nothing for a dimensionless run.
     */
    void
    set_si_unit_attributes(const UnitSystem &units);

    /// Write the file to FILENAME (whole or not at all); no writes after
    /// this.
    void
    finish();

  private:
    /// Record @p name in @p group as written; throws if it cannot be.
    void
    claim(const std::string &group, const std::string &name);

    /// The HDF5 id of @p group (the file for "/"), created on first use;
    /// the caller closes it with close_group().
    hid_t
    open_group(const std::string &group);
    void
    close_group(hid_t id) const;

    const std::string     filename;
    hid_t                 file = -1;
    std::set<std::string> written;
    bool                  finished = false;
  };
} // namespace DiskImpact
