#pragma once
// Typed, checked access to one TOML table: every read records the key as known, every wrong
// type or missing required key becomes a Diagnostic with the file, line and dotted key path.

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "numerics/time_table.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/scenario.hpp"
#include "scenario/spellings.hpp"

namespace hydrodda::scenario {

// Collects diagnostics and defaults for one file.
struct ReadContext {
  std::string file;
  std::vector<Diagnostic> errors;
  std::vector<DefaultUsed> defaults;

  void error(int line, std::string key, std::string message) {
    errors.push_back({file, line, std::move(key), std::move(message)});
  }
  // Whether `key` has had an error already (a value given but refused is not also "missing").
  bool has_error(std::string_view key) const {
    return std::any_of(errors.begin(), errors.end(), [&](const Diagnostic& d) { return d.key == key; });
  }
};

int line_of(const toml::node& node);

class TableView {
 public:
  // Reports every key of `table` not in `allowed`, suggesting the nearest allowed one.
  TableView(ReadContext& context, const toml::table& table, std::string path,
            const std::vector<std::string>& allowed);

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  int line() const { return line_; }
  int line_of_key(std::string_view key) const;  // the value's line, or the table's
  bool has(std::string_view key) const { return table_.contains(key); }
  const toml::node* node(std::string_view key) const { return table_.get(key); }

  std::optional<double> number(std::string_view key) const;
  // A whole number in [min, max]; outside it, an error that states the range. Every integer key
  // is read through this, so no value is narrowed to int unchecked.
  std::optional<int> integer(std::string_view key, int min, int max) const;
  std::optional<bool> boolean(std::string_view key) const;
  std::optional<std::string> string(std::string_view key) const;
  std::optional<Point> point(std::string_view key) const;
  // A value that may change in time (time_table_reading.cpp): a constant (a number, or a point
  // [fx, fy] when `columns` is 2) or a table of rows [t, v₁ … v_columns], at least two, the
  // times increasing.
  std::optional<numerics::TimeTable> time_table(std::string_view key, std::size_t columns = 1) const;
  std::optional<Polygon> points(std::string_view key) const;
  const toml::table* table(std::string_view key) const;
  // An array of tables ([[key]] or an array of inline tables).
  std::vector<const toml::table*> tables(std::string_view key) const;
  // An array of arrays of points, e.g. fractures or welded polygons.
  std::vector<std::pair<Polygon, int>> point_lists(std::string_view key) const;

  double required_number(std::string_view key) const;
  // The value, or `fallback` recorded as a default used.
  double number_or(std::string_view key, double fallback) const;
  // One of `choices` (index), or the index of `fallback` recorded as a default used.
  int choice(std::string_view key, const std::vector<std::string>& choices,
             const std::string& fallback) const;
  // One of Enum's values by its spelling (spellings.hpp), or `fallback` recorded as a default used.
  template <typename Enum>
  Enum choice(std::string_view key, Enum fallback) const {
    const auto& table = Spellings<Enum>::table;
    std::vector<std::string> texts;
    for (const Spelling<Enum>& s : table) texts.emplace_back(s.text);
    return table[choice(key, texts, std::string(spell(fallback)))].value;
  }

  // Range checks: add an error naming the key when `valid` is false.
  void require(std::string_view key, bool valid, const std::string& message) const;

 private:
  ReadContext& context_;
  const toml::table& table_;
  std::string path_;
  int line_;
};

// Point from a TOML node: an array of exactly two numbers.
std::optional<Point> to_point(ReadContext& context, const toml::node& node, const std::string& key);

std::string format_number(double value);

}  // namespace hydrodda::scenario
