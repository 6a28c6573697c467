#include "output/hdf5_output.h"

#include "base/unit_system.h"
#include "output/atomic_file.h"
#include "output/csv_table.h"

#include <filesystem>
#include <stdexcept>

namespace DiskImpact
{
  namespace
  {
    /**
     * While alive, replaces HDF5's automatic error printing by a record of
     * the first failure, so that a failed HDF5 call becomes an exception
     * (throw_if_failed()) instead of a page of text.
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
        if (failed)
          throw std::runtime_error("HDF5 error while " + what + ": " +
                                   description);
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

      /// Error-stack walker: the API call that failed.
      static herr_t
      describe(unsigned int n, const H5E_error2_t *error, void *data)
      {
        auto *self = static_cast<Hdf5ErrorRecorder *>(data);
        if (n == 0)
          self->description = std::string(error->func_name) +
                              "(): " + (error->desc ? error->desc : "");
        return 0;
      }

      H5E_auto2_t old_handler = nullptr;
      void       *old_data    = nullptr;
      bool        failed      = false;
      std::string description;
    };

    /// "group/name", or "/name" in the root group: for messages.
    std::string
    object_path(const std::string &group, const std::string &name)
    {
      return (group == "/" ? "" : group) + "/" + name;
    }
  } // namespace

  Hdf5Output::Hdf5Output(const std::string &filename)
      : filename(filename)
  {
    const auto directory = std::filesystem::path(filename).parent_path();
    if (!directory.empty() && !std::filesystem::is_directory(directory))
      throw std::runtime_error("cannot write " + filename + ": no directory " +
                               directory.string());
    Hdf5ErrorRecorder recorder;
    // In memory, no backing store: finish() writes the file image.
    const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_fapl_core(access, 1 << 16, 0);
    file = H5Fcreate(filename.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
    H5Pclose(access);
    recorder.throw_if_failed("creating " + filename + " in memory");
  }

  Hdf5Output::~Hdf5Output()
  {
    if (file >= 0)
      {
        Hdf5ErrorRecorder recorder;
        H5Fclose(file);
      }
  }

  hid_t
  Hdf5Output::open_group(const std::string &group)
  {
    if (group == "/")
      return file;
    if (H5Lexists(file, group.c_str(), H5P_DEFAULT) > 0)
      return H5Gopen2(file, group.c_str(), H5P_DEFAULT);
    return H5Gcreate2(
      file, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  }

  void
  Hdf5Output::close_group(const hid_t id) const
  {
    if (id != file && id >= 0)
      H5Gclose(id);
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
    Hdf5ErrorRecorder recorder;
    const hid_t       parent  = open_group(group);
    const hsize_t     size    = values.size();
    const hid_t       space   = H5Screate_simple(1, &size, nullptr);
    const hid_t       dataset = H5Dcreate2(parent,
                                     name.c_str(),
                                     H5T_NATIVE_DOUBLE,
                                     space,
                                     H5P_DEFAULT,
                                     H5P_DEFAULT,
                                     H5P_DEFAULT);
    if (!values.empty())
      H5Dwrite(dataset,
               H5T_NATIVE_DOUBLE,
               H5S_ALL,
               H5S_ALL,
               H5P_DEFAULT,
               values.data());
    H5Dclose(dataset);
    H5Sclose(space);
    close_group(parent);
    recorder.throw_if_failed("writing dataset " + object_path(group, name) +
                             " of " + filename);
  }

  void
  Hdf5Output::set_attribute(const std::string &group,
                            const std::string &name,
                            const double       value)
  {
    claim(group, name);
    Hdf5ErrorRecorder recorder;
    const hid_t       parent    = open_group(group);
    const hid_t       space     = H5Screate(H5S_SCALAR);
    const hid_t       attribute = H5Acreate2(
      parent, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, H5T_NATIVE_DOUBLE, &value);
    H5Aclose(attribute);
    H5Sclose(space);
    close_group(parent);
    recorder.throw_if_failed("writing attribute " + object_path(group, name) +
                             " of " + filename);
  }

  void
  Hdf5Output::set_attribute(const std::string &group,
                            const std::string &name,
                            const std::string &value)
  {
    claim(group, name);
    Hdf5ErrorRecorder recorder;
    const hid_t       parent = open_group(group);
    // A variable-length UTF-8 string, as h5py writes str attributes.
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute =
      H5Acreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    const char *text = value.c_str();
    H5Awrite(attribute, type, &text);
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
    close_group(parent);
    recorder.throw_if_failed("writing attribute " + object_path(group, name) +
                             " of " + filename);
  }

  void
  Hdf5Output::set_si_unit_attributes(const UnitSystem &units)
  {
    if (!units.is_si())
      return;
    set_attribute("/", "length_unit_m", units.length());
    set_attribute("/", "time_unit_s", units.time());
    set_attribute("/", "speed_unit_m_per_s", units.speed());
    set_attribute("/", "force_unit", units.force());
    set_attribute("/", "force_unit_name", units.force_name());
    set_attribute("/", "energy_unit", units.force() * units.length());
    set_attribute("/",
                  "energy_unit_name",
                  units.force_name() == "N" ? "J" : "J/m");
  }

  void
  Hdf5Output::finish()
  {
    if (finished)
      throw std::logic_error("Hdf5Output: " + filename + " finished twice");
    std::string image;
    {
      Hdf5ErrorRecorder recorder;
      H5Fflush(file, H5F_SCOPE_GLOBAL);
      const ssize_t size = H5Fget_file_image(file, nullptr, 0);
      if (size > 0)
        {
          image.resize(size);
          H5Fget_file_image(file, image.data(), size);
        }
      recorder.throw_if_failed("building " + filename);
    }
    finished = true;
    write_atomically(filename, image);
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
} // namespace DiskImpact
