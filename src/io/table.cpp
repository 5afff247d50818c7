// Table: CSV out with fmt's shortest round-trip formatting ("{}": Dragonbox),
// CSV in with strtod, which reads those decimals back to the same bits.
#include "io/table.h"

#include "core/bounded_read.h"
#include "core/error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace grainlab {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

}  // namespace

void Table::add_row(std::vector<double> row) {
  if (row.size() != columns.size())
    throw std::invalid_argument(
        fmt::format("Table::add_row: row has {} values, the table {} columns", row.size(), columns.size()));
  rows.push_back(std::move(row));
}

std::size_t Table::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::out_of_range(fmt::format("Table: no column '{}'", name));
}

std::string Table::to_csv() const {
  fmt::memory_buffer out;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i].find_first_of(",\"\n\r") != std::string::npos)
      throw std::invalid_argument(fmt::format("Table: column name '{}' holds a comma, quote or line break", columns[i]));
    fmt::format_to(std::back_inserter(out), "{}{}", i ? "," : "", columns[i]);
  }
  out.push_back('\n');
  for (const std::vector<double>& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) fmt::format_to(std::back_inserter(out), "{}{}", i ? "," : "", row[i]);
    out.push_back('\n');
  }
  return fmt::to_string(out);
}

Table parse_csv(const std::string& text, const std::string& source_name) {
  Table t;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1) {
      if (line.empty()) input_error("{} (line 1): empty header; a CSV table starts with its column names", source_name);
      t.columns = split(line);
      continue;
    }
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != t.columns.size())
      input_error("{} (line {}): {} values, but the header has {} columns; the file is damaged or cut short",
                  source_name, line_no, cells.size(), t.columns.size());
    std::vector<double> row(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const char* begin = cells[i].c_str();
      char* end = nullptr;
      errno = 0;
      row[i] = std::strtod(begin, &end);
      // ERANGE on underflow still yields the right subnormal; only refuse text that is not a number.
      if (end == begin || *end != '\0')
        input_error("{} (line {}, column '{}'): '{}' is not a number", source_name, line_no, t.columns[i], cells[i]);
    }
    t.rows.push_back(std::move(row));
  }
  if (line_no == 0) input_error("{}: empty file; a CSV table starts with its column names", source_name);
  return t;
}

Table read_csv(const std::filesystem::path& path) {
  return parse_csv(read_bounded_file(path, 1024 * kMiB, "CSV table"), path.string());
}

}  // namespace grainlab
