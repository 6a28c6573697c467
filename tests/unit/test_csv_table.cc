// CsvTable: columns read back as numbers, empty cells as NaN, and the
// errors for unknown columns, text cells and incomplete rows.

#include "output/csv_table.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
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
