// HDF5 output: tables, vectors and attributes read back with deal.II's HDF5
// reader, the atomic write (FILENAME appears only on finish()), and the
// errors.

#include "output/csv_table.h"
#include "output/hdf5_output.h"

#include <deal.II/base/hdf5.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

using namespace DiskImpact;
namespace fs = std::filesystem;

namespace
{
  /// A fresh, empty directory for one test, deleted at the end.
  class ScratchDirectory
  {
  public:
    explicit ScratchDirectory(const std::string &name)
        : path(fs::temp_directory_path() /
               ("diskimpact_" + name + "_" + std::to_string(getpid())))
    {
      fs::remove_all(path);
      fs::create_directories(path);
    }

    ~ScratchDirectory()
    {
      fs::remove_all(path);
    }

    std::string
    file(const std::string &name) const
    {
      return (path / name).string();
    }

  private:
    const fs::path path;
  };

  /// The group @p group of @p file: "/" is the root.
  dealii::HDF5::Group
  open_group_or_root(const dealii::HDF5::File &file, const std::string &group)
  {
    if (group == "/")
      return file;
    return file.open_group(group);
  }

  /**
   * Dataset @p name of group @p group in the HDF5 file @p filename. The file
   * is closed on return: deal.II aborts if an HDF5 object is destroyed while
   * a failed REQUIRE unwinds the stack.
   */
  std::vector<double>
  read_dataset(const std::string &filename,
               const std::string &group,
               const std::string &name)
  {
    const dealii::HDF5::File file(filename,
                                  dealii::HDF5::File::FileAccessMode::open);
    return open_group_or_root(file, group)
      .open_dataset(name)
      .read<std::vector<double>>();
  }

  /// The dimensions of dataset @p name of group @p group in @p filename.
  std::vector<hsize_t>
  dataset_dimensions(const std::string &filename,
                     const std::string &group,
                     const std::string &name)
  {
    const dealii::HDF5::File file(filename,
                                  dealii::HDF5::File::FileAccessMode::open);
    return open_group_or_root(file, group).open_dataset(name).get_dimensions();
  }

  /// Attribute @p name of group @p group in the HDF5 file @p filename.
  template <typename T>
  T
  read_attribute(const std::string &filename,
                 const std::string &group,
                 const std::string &name)
  {
    const dealii::HDF5::File file(filename,
                                  dealii::HDF5::File::FileAccessMode::open);
    return open_group_or_root(file, group).get_attribute<T>(name);
  }
} // namespace

TEST_CASE("Hdf5Output: table, vector and attributes read back exactly",
          "[hdf5]")
{
  const ScratchDirectory directory("hdf5_roundtrip");
  const std::string      filename = directory.file("impact.h5");

  const std::vector<double> time   = {0., 0.25, 1. / 3., -3.5e-300, 1e300};
  const std::vector<double> energy = {1., 0.999999999999, 0.5, 0., -0.};
  const std::vector<double> displacement = {1e-17, -2. / 7., 42.};

  Hdf5Output output(filename);
  output.write_table("time_series", {"time", "energy"}, {time, energy});
  output.write_vector("final_state", "displacement", displacement);
  output.write_vector("final_state", "velocity", {});
  output.set_attribute("/", "velocity", 0.1);
  output.set_attribute("/", "units", "c = sqrt(E2/rho), R = 1");
  output.set_attribute("time_series", "n_steps", 4);

  // Built in memory: nothing on disk before finish().
  CHECK_FALSE(fs::exists(filename));
  CHECK_FALSE(fs::exists(filename + ".tmp"));
  output.finish();
  CHECK(fs::exists(filename));
  CHECK_FALSE(fs::exists(filename + ".tmp"));

  CHECK(read_dataset(filename, "time_series", "time") == time);
  CHECK(read_dataset(filename, "time_series", "energy") == energy);
  CHECK(read_dataset(filename, "final_state", "displacement") == displacement);
  CHECK(dataset_dimensions(filename, "final_state", "velocity") ==
        std::vector<hsize_t>{0});
  CHECK(read_attribute<double>(filename, "/", "velocity") == 0.1);
  CHECK(read_attribute<std::string>(filename, "/", "units") ==
        "c = sqrt(E2/rho), R = 1");
  CHECK(read_attribute<double>(filename, "time_series", "n_steps") == 4.);
}

TEST_CASE("Hdf5Output: a CsvTable's columns, empty cells as NaN", "[hdf5]")
{
  const ScratchDirectory directory("hdf5_csv");
  const std::string      filename = directory.file("modes.h5");

  CsvTable table({"rank", "omega", "fraction"});
  table.start_row();
  table.add(1);
  table.add(2.5);
  table.add(0.001);
  table.start_row();
  table.add(2u);
  table.add(1e-300);
  table.add_empty();

  {
    Hdf5Output output(filename);
    output.write_table("modes", table);
    output.finish();
  }

  CHECK(read_dataset(filename, "modes", "rank") == std::vector<double>{1., 2.});
  CHECK(read_dataset(filename, "modes", "omega") ==
        std::vector<double>{2.5, 1e-300});
  const auto fraction = read_dataset(filename, "modes", "fraction");
  REQUIRE(fraction.size() == 2);
  CHECK(fraction[0] == 0.001);
  CHECK(std::isnan(fraction[1]));
}

TEST_CASE("Hdf5Output: no file without finish()", "[hdf5]")
{
  const ScratchDirectory directory("hdf5_unfinished");
  const std::string      filename = directory.file("run.h5");

  SECTION("a writer destroyed early leaves nothing")
  {
    {
      Hdf5Output output(filename);
      output.write_vector("final_state", "displacement", {1., 2.});
    }
    CHECK_FALSE(fs::exists(filename));
    CHECK_FALSE(fs::exists(filename + ".tmp"));
  }

  SECTION("an exception during the run leaves nothing")
  {
    const auto run = [&filename]() {
      Hdf5Output output(filename);
      output.set_attribute("/", "velocity", 0.1);
      throw std::runtime_error("solver diverged");
    };
    CHECK_THROWS_AS(run(), std::runtime_error);
    CHECK_FALSE(fs::exists(filename));
    CHECK_FALSE(fs::exists(filename + ".tmp"));
  }
}

TEST_CASE("Hdf5Output: misuse throws", "[hdf5]")
{
  const ScratchDirectory directory("hdf5_errors");
  const std::string      filename = directory.file("run.h5");

  CHECK_THROWS_AS(Hdf5Output(directory.file("missing/run.h5")),
                  std::runtime_error);
  CHECK_FALSE(fs::exists(directory.file("missing")));

  Hdf5Output output(filename);
  output.write_vector("state", "u", {1.});
  CHECK_THROWS_AS(output.write_vector("state", "u", {2.}),
                  std::invalid_argument);
  CHECK_THROWS_AS(output.set_attribute("state", "u", 1.),
                  std::invalid_argument);
  CHECK_THROWS_AS(output.write_table("table", {"a", "b"}, {{1., 2.}, {3.}}),
                  std::invalid_argument);
  CHECK_THROWS_AS(output.write_table("table", {"a"}, {{1.}, {2.}}),
                  std::invalid_argument);

  CsvTable labelled({"n", "family"});
  labelled.start_row();
  labelled.add(2);
  labelled.add(std::string("radial"));
  CHECK_THROWS_AS(output.write_table("modes", labelled), std::invalid_argument);

  output.finish();
  CHECK(fs::exists(filename));
  CHECK_THROWS_AS(output.write_vector("state", "v", {1.}), std::logic_error);
  CHECK_THROWS_AS(output.finish(), std::logic_error);
}

TEST_CASE("Hdf5Output: a full disk throws one line and leaves no file",
          "[hdf5]")
{
  const ScratchDirectory directory("hdf5_full_disk");
  const std::string      filename = directory.file("run.h5");
  const std::string      old_text = "an older run.h5";
  // The temporary file is a full device: every write fails with ENOSPC.
  fs::create_symlink("/dev/full", filename + ".tmp");
  std::ofstream(filename) << old_text;

  Hdf5Output output(filename);
  output.write_vector("state", "u", {1., 2.});
  try
    {
      output.finish();
      FAIL("no exception");
    }
  catch (const std::runtime_error &error)
    {
      const std::string message = error.what();
      CAPTURE(message);
      CHECK(message ==
            "cannot write " + filename + ": No space left on device");
    }
  // The older file is untouched, no temporary file is left.
  std::string text;
  std::getline(std::ifstream(filename), text);
  CHECK(text == old_text);
  CHECK_FALSE(fs::exists(filename + ".tmp"));
}
