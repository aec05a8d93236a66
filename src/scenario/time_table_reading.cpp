// Reading a value that may change in time: a constant, or a table of (time, value) rows
// (docs/scenario.md, "Loads over time"). Each refusal names the row's line and the key.

#include <fmt/format.h>

#include <cmath>

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

namespace {

std::string row_form(std::size_t columns) { return columns == 1 ? "[t, value]" : "[t, fx, fy]"; }

// One row [t, v₁ … v_columns] appended to `times` and `values`; false (with its error) if it is
// not one.
bool read_row(ReadContext& context, const toml::node& node, const std::string& key, std::size_t columns,
              std::vector<double>& times, std::vector<double>& values) {
  const toml::array* row = node.as_array();
  const bool numbers = row && row->size() == columns + 1 &&
                       std::all_of(row->begin(), row->end(), [](const toml::node& n) { return n.is_number(); });
  if (!numbers) {
    context.error(line_of(node), key, fmt::format("expected a row {} of {} numbers", row_form(columns), columns + 1));
    return false;
  }
  for (std::size_t i = 0; i <= columns; ++i) {
    const double v = *(*row)[i].value<double>();
    if (!std::isfinite(v)) {
      context.error(line_of(node), key, "a table's times and values must be finite numbers");
      return false;
    }
    (i == 0 ? times : values).push_back(v);
  }
  if (times.size() > 1 && !(times.back() > times[times.size() - 2])) {
    context.error(line_of(node), key,
                  fmt::format("the times must increase from row to row: row {} (t = {:g}) is not later than row {} "
                              "(t = {:g})", times.size(), times.back(), times.size() - 1, times[times.size() - 2]));
    return false;
  }
  return true;
}

}  // namespace

std::optional<numerics::TimeTable> TableView::time_table(std::string_view key, std::size_t columns) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  const std::string path = key_path(key);
  const toml::array* rows = n->as_array();
  // A constant: a number, or a point.
  if (columns == 1 && !rows) {
    const std::optional<double> v = number(key);
    return v ? std::optional<numerics::TimeTable>(*v) : std::nullopt;
  }
  if (rows && (rows->empty() || !(*rows)[0].is_array())) {
    if (columns != 2) {
      context_.error(line_of(*n), path, fmt::format("expected a number or a table of rows {}", row_form(columns)));
      return std::nullopt;
    }
    const std::optional<Point> p = to_point(context_, *n, path);
    if (!p) return std::nullopt;
    const double values[2]{p->x, p->y};
    return numerics::TimeTable::constant(values);
  }
  if (!rows) {
    context_.error(line_of(*n), path, fmt::format("expected a point [fx, fy] or a table of rows {}", row_form(columns)));
    return std::nullopt;
  }
  std::vector<double> times, values;
  for (const toml::node& row : *rows)
    if (!read_row(context_, row, path, columns, times, values)) return std::nullopt;
  if (times.size() < 2) {
    context_.error(line_of(*n), path,
                   fmt::format("a time table needs at least two rows {}, linear between them; give {} for a "
                               "constant", row_form(columns), columns == 1 ? "a number" : "[fx, fy]"));
    return std::nullopt;
  }
  return numerics::TimeTable(std::move(times), std::move(values), columns);
}

}  // namespace hydrodda::scenario
