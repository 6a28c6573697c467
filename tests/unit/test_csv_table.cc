// CsvTable: columns read back as numbers, empty cells as NaN, the errors
// for unknown columns, text cells and incomplete rows; files read back and
// written whole or not at all.

#include "output/csv_table.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

using namespace DiskImpact;

TEST_CASE("CsvTable: a column parsed back", "[csv]")
{
  CsvTable table({"n", "omega", "family"});
  table.start_row();
  table.add(3);
  table.add(1. / 3.);
  table.add(std::string("radial"));
  table.start_row();
  table.add(-1);
  table.add_empty();
  table.add(std::string("mixed"));

  CHECK(table.column_names() ==
        std::vector<std::string>{"n", "omega", "family"});
  CHECK(table.column("n") == std::vector<double>{3., -1.});

  const auto omega = table.column("omega");
  REQUIRE(omega.size() == 2);
  CHECK(omega[0] == std::stod(CsvTable::format(1. / 3.)));
  CHECK(std::isnan(omega[1]));

  CHECK_THROWS_AS(table.column("family"), std::invalid_argument);
  CHECK_THROWS_AS(table.column("energy"), std::invalid_argument);

  table.start_row();
  table.add(4);
  CHECK_THROWS_AS(table.column("n"), std::logic_error);
}

TEST_CASE("CsvTable: NaN written as an empty cell, read back", "[csv]")
{
  const std::string filename =
    std::filesystem::temp_directory_path() /
    ("diskimpact_csv_" + std::to_string(getpid()) + ".csv");
  CsvTable table({"v", "epsilon", "status"});
  table.start_row();
  table.add(0.1);
  table.add(std::nan(""));
  table.add(std::string("pending"));
  table.write(filename);

  std::string   header, row;
  std::ifstream in(filename);
  std::getline(in, header);
  std::getline(in, row);
  CHECK(row == "0.1,,pending");

  const CsvTable again = CsvTable::read(filename);
  CHECK(again.column_names() == table.column_names());
  CHECK(again.row(0) == std::vector<std::string>{"0.1", "", "pending"});
  std::filesystem::remove(filename);
}

TEST_CASE("write_atomically: a full disk leaves the older file", "[csv]")
{
  const std::filesystem::path directory =
    std::filesystem::temp_directory_path() /
    ("diskimpact_atomic_" + std::to_string(getpid()));
  std::filesystem::create_directories(directory);
  const std::string filename = directory / "summary.csv";
  std::ofstream(filename) << "old\n";
  // Every write to the temporary file fails with ENOSPC, as on a full disk.
  std::filesystem::create_symlink("/dev/full", filename + ".tmp");

  CsvTable table({"epsilon"});
  table.start_row();
  table.add(0.9);
  try
    {
      table.write(filename);
      FAIL("no exception");
    }
  catch (const std::runtime_error &e)
    {
      CHECK(std::string(e.what()) ==
            "cannot write " + filename + ": No space left on device");
    }
  std::string text;
  std::getline(std::ifstream(filename), text);
  CHECK(text == "old");
  CHECK_FALSE(std::filesystem::exists(filename + ".tmp"));
  std::filesystem::remove_all(directory);
}
