#include "output/hdf5_output.h"

#include "output/csv_table.h"

#include <deal.II/base/hdf5.h>

#include <cstdio>
#include <fstream>
#include <hdf5.h>
#include <stdexcept>

namespace DiskImpact
{
  namespace
  {
    /**
     * While alive, replaces HDF5's automatic error printing by a record of
     * the failures, so that a failed HDF5 call (which deal.II checks only
     * in Debug builds) becomes an exception.
     */
    class Hdf5ErrorRecorder
    {
    public:
      Hdf5ErrorRecorder()
      {
        H5Eget_auto2(H5E_DEFAULT, &old_handler, &old_data);
        H5Eset_auto2(H5E_DEFAULT, &record, this);
      }

      ~Hdf5ErrorRecorder()
      {
        H5Eset_auto2(H5E_DEFAULT, old_handler, old_data);
      }

      Hdf5ErrorRecorder(const Hdf5ErrorRecorder &) = delete;
      Hdf5ErrorRecorder &
      operator=(const Hdf5ErrorRecorder &) = delete;

      /// Throw std::runtime_error if an HDF5 call failed while @p what ran.
      void
      throw_if_failed(const std::string &what) const
      {
        if (!failed)
          return;
        std::string message = "HDF5 error while " + what + ": " + outermost;
        if (innermost != outermost)
          message += " (" + innermost + ")";
        throw std::runtime_error(message);
      }

    private:
      /// HDF5's error callback: keep the description of the first failure.
      static herr_t
      record(hid_t stack, void *data)
      {
        auto *self = static_cast<Hdf5ErrorRecorder *>(data);
        if (!self->failed)
          H5Ewalk2(stack, H5E_WALK_DOWNWARD, &describe, self);
        self->failed = true;
        return 0;
      }

      /// Error-stack walker, from the API call down to the cause.
      static herr_t
      describe(unsigned int n, const H5E_error2_t *error, void *data)
      {
        auto *self      = static_cast<Hdf5ErrorRecorder *>(data);
        self->innermost = std::string(error->func_name) +
                          "(): " + (error->desc ? error->desc : "");
        if (n == 0)
          self->outermost = self->innermost;
        return 0;
      }

      H5E_auto2_t old_handler = nullptr;
      void       *old_data    = nullptr;
      bool        failed      = false;
      std::string outermost;
      std::string innermost;
    };

    /**
     * Open the HDF5 file @p path, apply @p operation to its group @p group
     * (created first if @p create), and close the file; then throw
     * std::runtime_error about @p what if an HDF5 call failed. No HDF5
     * object outlives the call, and @p operation must not throw.
     */
    template <typename Operation>
    void
    with_group(const std::string &path,
               const std::string &group,
               const bool         create,
               const std::string &what,
               Operation        &&operation)
    {
      Hdf5ErrorRecorder recorder;
      {
        dealii::HDF5::File file(path, dealii::HDF5::File::FileAccessMode::open);
        if (group == "/")
          operation(file);
        else
          {
            dealii::HDF5::Group handle =
              create ? file.create_group(group) : file.open_group(group);
            operation(handle);
          }
      }
      recorder.throw_if_failed(what);
    }

    /// Create (or truncate) the HDF5 file @p path.
    void
    create_file(const std::string &path)
    {
      if (!std::ofstream(path))
        throw std::runtime_error("cannot write " + path);
      Hdf5ErrorRecorder recorder;
      {
        dealii::HDF5::File file(path,
                                dealii::HDF5::File::FileAccessMode::create);
      }
      recorder.throw_if_failed("creating " + path);
    }

    /// "group/name", or "/name" in the root group: for messages.
    std::string
    object_path(const std::string &group, const std::string &name)
    {
      return (group == "/" ? "" : group) + "/" + name;
    }
  } // namespace

  Hdf5Output::Hdf5Output(const std::string &filename)
      : filename(filename)
      , temporary(filename + ".tmp")
  {
    try
      {
        create_file(temporary);
      }
    catch (...)
      {
        std::remove(temporary.c_str());
        throw;
      }
  }

  Hdf5Output::~Hdf5Output()
  {
    if (!finished)
      std::remove(temporary.c_str());
  }

  void
  Hdf5Output::write_table(const std::string                      &group,
                          const std::vector<std::string>         &column_names,
                          const std::vector<std::vector<double>> &columns)
  {
    if (column_names.size() != columns.size())
      throw std::invalid_argument(
        "Hdf5Output: " + std::to_string(column_names.size()) +
        " column names for " + std::to_string(columns.size()) +
        " columns in group '" + group + "'");
    for (const auto &column : columns)
      if (column.size() != columns.front().size())
        throw std::invalid_argument("Hdf5Output: columns of unequal length "
                                    "in group '" +
                                    group + "'");
    for (unsigned int c = 0; c < columns.size(); ++c)
      write_vector(group, column_names[c], columns[c]);
  }

  void
  Hdf5Output::write_table(const std::string &group, const CsvTable &table)
  {
    std::vector<std::vector<double>> columns;
    for (const auto &name : table.column_names())
      columns.push_back(table.column(name));
    write_table(group, table.column_names(), columns);
  }

  void
  Hdf5Output::write_vector(const std::string         &group,
                           const std::string         &name,
                           const std::vector<double> &values)
  {
    claim(group, name);
    with_group(temporary,
               group,
               is_new_group(group),
               "writing dataset " + object_path(group, name) + " to " +
                 temporary,
               [&](dealii::HDF5::Group &handle) {
                 auto dataset = handle.create_dataset<double>(
                   name, {static_cast<hsize_t>(values.size())});
                 if (!values.empty())
                   dataset.write(values);
               });
  }

  namespace
  {
    /// Attribute @p name = @p value of @p group in the file @p path.
    template <typename T>
    void
    write_attribute(const std::string &path,
                    const std::string &group,
                    const bool         create_group,
                    const std::string &name,
                    const T           &value)
    {
      with_group(path,
                 group,
                 create_group,
                 "writing attribute " + object_path(group, name) + " to " +
                   path,
                 [&](dealii::HDF5::Group &handle) {
                   handle.set_attribute<T>(name, value);
                 });
    }
  } // namespace

  void
  Hdf5Output::set_attribute(const std::string &group,
                            const std::string &name,
                            const double       value)
  {
    claim(group, name);
    write_attribute(temporary, group, is_new_group(group), name, value);
  }

  void
  Hdf5Output::set_attribute(const std::string &group,
                            const std::string &name,
                            const std::string &value)
  {
    claim(group, name);
    write_attribute(temporary, group, is_new_group(group), name, value);
  }

  void
  Hdf5Output::finish()
  {
    if (finished)
      throw std::logic_error("Hdf5Output: " + filename + " finished twice");
    if (std::rename(temporary.c_str(), filename.c_str()) != 0)
      throw std::runtime_error("cannot rename " + temporary + " to " +
                               filename);
    finished = true;
  }

  void
  Hdf5Output::claim(const std::string &group, const std::string &name)
  {
    if (finished)
      throw std::logic_error("Hdf5Output: write to " + filename +
                             " after finish()");
    if (group.empty() || (group != "/" && group.find('/') != std::string::npos))
      throw std::invalid_argument("Hdf5Output: '" + group +
                                  "' is not a valid group name");
    if (name.empty() || name.find('/') != std::string::npos)
      throw std::invalid_argument("Hdf5Output: '" + name +
                                  "' is not a valid name in group '" + group +
                                  "'");
    if (!written.insert(object_path(group, name)).second)
      throw std::invalid_argument("Hdf5Output: " + object_path(group, name) +
                                  " is written twice in " + filename);
  }

  bool
  Hdf5Output::is_new_group(const std::string &group)
  {
    return group != "/" && created_groups.insert(group).second;
  }
} // namespace DiskImpact
