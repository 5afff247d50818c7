// A small column table for series.csv: a header of column names, then one
// row of numbers per sample, each written as the shortest decimal that reads
// back to the same double, so a resumed run can be compared bit for bit.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace grainlab {

// Named columns of doubles.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  // Appends a row; throws std::invalid_argument if its width is not columns.size().
  void add_row(std::vector<double> row);
  // Index of the named column; throws std::out_of_range if there is none.
  std::size_t column(const std::string& name) const;
  // The CSV text: header line, then rows; exact (shortest round-trip) doubles, '\n' line ends.
  std::string to_csv() const;
};

// Reads a CSV written by Table::to_csv; throws InputError naming the file and line on bad input.
Table read_csv(const std::filesystem::path& path);

// Parses CSV text; source_name is used in messages.
Table parse_csv(const std::string& text, const std::string& source_name);

}  // namespace grainlab
