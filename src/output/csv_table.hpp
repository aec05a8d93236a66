#pragma once
// A CSV table kept in memory and written whole (atomically) after each addition, so that a
// file in the run folder is always complete up to its last row.

#include <string>
#include <vector>

namespace hydrodda::output {

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns);

  // Cells in column order; numbers with full double precision.
  void add_row(const std::vector<std::string>& cells);
  std::string text() const { return text_; }
  std::size_t rows() const { return rows_; }

  static std::string cell(double value);
  static std::string cell(long long value);

 private:
  std::size_t columns_;
  std::size_t rows_ = 0;
  std::string text_;
};

}  // namespace hydrodda::output
