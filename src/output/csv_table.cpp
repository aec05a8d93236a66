#include "output/csv_table.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace hydrodda::output {

namespace {
// Quotes a cell that holds a separator, a quote or a line break (RFC 4180).
std::string escape(const std::string& cell) {
  if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
  std::string out(1, '"');
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string join(const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) line += ',';
    line += escape(cells[i]);
  }
  line += '\n';
  return line;
}
}  // namespace

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(columns.size()), text_(join(columns)) {}

void CsvTable::add_row(const std::vector<std::string>& cells) {
  if (cells.size() != columns_)
    throw std::logic_error(fmt::format("CSV row has {} cells, the table {} columns", cells.size(), columns_));
  text_ += join(cells);
  ++rows_;
}

std::string CsvTable::cell(double value) { return fmt::format("{:.17g}", value); }
std::string CsvTable::cell(long long value) { return fmt::format("{}", value); }

}  // namespace hydrodda::output
