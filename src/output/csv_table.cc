#include "output/csv_table.h"

#include "output/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
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
    // A value that does not exist (NaN) is an empty cell.
    add(std::isnan(value) ? std::string() : format(value));
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

  const std::vector<std::string> &
  CsvTable::column_names() const
  {
    return header;
  }

  namespace
  {
    /// A cell as a number: NaN if empty; throws unless it is all a number.
    double
    parse_cell(const std::string &cell, const std::string &where)
    {
      if (cell.empty())
        return std::numeric_limits<double>::quiet_NaN();
      char        *end   = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      if (end != cell.c_str() + cell.size())
        throw std::invalid_argument("CsvTable: " + where + " holds '" + cell +
                                    "', which is not a number");
      return value;
    }
  } // namespace

  std::vector<double>
  CsvTable::column(const std::string &name) const
  {
    const auto          cells = text_column(name);
    std::vector<double> values;
    values.reserve(cells.size());
    for (unsigned int r = 0; r < cells.size(); ++r)
      values.push_back(
        parse_cell(cells[r],
                   "column '" + name + "', row " + std::to_string(r)));
    return values;
  }

  std::vector<std::string>
  CsvTable::text_column(const std::string &name) const
  {
    const auto found = std::find(header.begin(), header.end(), name);
    if (found == header.end())
      throw std::invalid_argument("CsvTable: no column named '" + name + "'");
    const std::size_t        index = found - header.begin();
    std::vector<std::string> cells;
    cells.reserve(rows.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        if (rows[r].size() != header.size())
          throw std::logic_error("CsvTable: row " + std::to_string(r) +
                                 " is incomplete");
        cells.push_back(rows[r][index]);
      }
    return cells;
  }

  void
  CsvTable::write(const std::string &filename) const
  {
    write_atomically(filename, [this](std::ostream &out) {
      auto write_line = [&out](const std::vector<std::string> &cells) {
        for (unsigned int i = 0; i < cells.size(); ++i)
          out << (i > 0 ? "," : "") << cells[i];
        out << '\n';
      };
      write_line(header);
      for (const auto &row : rows)
        write_line(row);
    });
  }

  CsvTable
  CsvTable::read(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw std::runtime_error("cannot read " + filename);
    auto split = [](const std::string &line) {
      std::vector<std::string> cells;
      std::stringstream        stream(line);
      std::string              cell;
      while (std::getline(stream, cell, ','))
        cells.push_back(cell);
      if (!line.empty() && line.back() == ',')
        cells.emplace_back();
      return cells;
    };
    std::string line;
    if (!std::getline(in, line))
      throw std::runtime_error(filename + " is empty");
    CsvTable table(split(line));
    while (std::getline(in, line))
      {
        const auto cells = split(line);
        if (cells.size() != table.header.size())
          throw std::runtime_error(
            filename + ": a row has " + std::to_string(cells.size()) +
            " cells, the header " + std::to_string(table.header.size()));
        table.rows.push_back(cells);
      }
    return table;
  }

  std::vector<std::string>
  CsvTable::row(const unsigned int index) const
  {
    return rows.at(index);
  }
} // namespace DiskImpact
