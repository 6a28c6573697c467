#include "csv_table.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace DiskImpact
{
  CsvTable::CsvTable(const std::vector<std::string> &column_names)
      : header(column_names)
  {
  }

  void
  CsvTable::start_row()
  {
    if (!rows.empty() && rows.back().size() != header.size())
      throw std::logic_error("CsvTable: previous row is incomplete");
    rows.emplace_back();
  }

  std::string
  CsvTable::format(const double value)
  {
    std::ostringstream out;
    out.precision(15);
    out << value;
    return out.str();
  }

  void
  CsvTable::add(const double value)
  {
    add(format(value));
  }

  void
  CsvTable::add(const long long value)
  {
    add(std::to_string(value));
  }

  void
  CsvTable::add(const unsigned int value)
  {
    add(std::to_string(value));
  }

  void
  CsvTable::add(const int value)
  {
    add(std::to_string(value));
  }

  void
  CsvTable::add(const std::string &text)
  {
    if (rows.empty() || rows.back().size() >= header.size())
      throw std::logic_error("CsvTable: add() without room in the row");
    rows.back().push_back(text);
  }

  void
  CsvTable::add_empty()
  {
    add(std::string());
  }

  unsigned int
  CsvTable::n_rows() const
  {
    return rows.size();
  }

  void
  CsvTable::write(const std::string &filename) const
  {
    const std::string temporary = filename + ".tmp";
    {
      std::ofstream out(temporary);
      if (!out)
        throw std::runtime_error("cannot write " + temporary);
      auto write_line = [&out](const std::vector<std::string> &cells) {
        for (unsigned int i = 0; i < cells.size(); ++i)
          out << (i > 0 ? "," : "") << cells[i];
        out << '\n';
      };
      write_line(header);
      for (const auto &row : rows)
        write_line(row);
      if (!out)
        throw std::runtime_error("error while writing " + temporary);
    }
    if (std::rename(temporary.c_str(), filename.c_str()) != 0)
      throw std::runtime_error("cannot rename " + temporary + " to " +
                               filename);
  }
} // namespace DiskImpact
