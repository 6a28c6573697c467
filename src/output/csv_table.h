#pragma once

#include <string>
#include <vector>

namespace DiskImpact
{
  /**
   * A CSV table: a header line and rows of cells, numbers with 15
   * significant digits. Written atomically (a temporary file renamed into
   * place), so a reader never sees a half-written table.
   */
  class CsvTable
  {
  public:
    explicit CsvTable(const std::vector<std::string> &column_names);

    /// Start a new row; cells are then added left to right.
    void
    start_row();
    void
    add(double value);
    void
    add(long long value);
    void
    add(unsigned int value);
    void
    add(int value);
    void
    add(const std::string &text);
    /// An empty cell (a value that does not exist for this row).
    void
    add_empty();

    unsigned int
    n_rows() const;

    /// The header: the column names, left to right.
    const std::vector<std::string> &
    column_names() const;

    /**
     * The cells of column @p name parsed back into numbers; an empty cell
     * gives NaN. Throws std::invalid_argument if there is no such column or
     * a cell is not a number, std::logic_error if a row is incomplete.
     */
    std::vector<double>
    column(const std::string &name) const;
    /// The cells of column @p name as written (same errors as column()).
    std::vector<std::string>
    text_column(const std::string &name) const;

    /// Write to @p filename whole or not at all (write_atomically()).
    void
    write(const std::string &filename) const;

    /// A table written by write(); throws std::runtime_error if the file
    /// cannot be read or a row's length differs from the header's.
    static CsvTable
    read(const std::string &filename);

    /// The cells of row @p index as written.
    std::vector<std::string>
    row(unsigned int index) const;

    /// Format a number the way the table does.
    static std::string
    format(double value);

  private:
    std::vector<std::string>              header;
    std::vector<std::vector<std::string>> rows;
  };
} // namespace DiskImpact
