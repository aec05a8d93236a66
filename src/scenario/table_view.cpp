#include "scenario/table_view.hpp"

#include <fmt/format.h>

#include <sstream>

namespace hydrodda::scenario {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

std::string format_number(double value) { return fmt::format("{:g}", value); }

namespace {
std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date or time";
  }
}
}  // namespace

TableView::TableView(ReadContext& context, const toml::table& table, std::string path,
                     const std::vector<std::string>& allowed)
    : context_(context), table_(table), path_(std::move(path)), line_(line_of(table)) {
  for (auto&& [key, value] : table_) {
    const std::string name{key.str()};
    if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
    std::string message = "unknown key";
    const std::string nearest = suggest_nearest(name, allowed);
    if (!nearest.empty()) message += fmt::format(" (did you mean '{}'?)", nearest);
    context_.error(static_cast<int>(key.source().begin.line) > 0
                       ? static_cast<int>(key.source().begin.line)
                       : line_of(value),
                   key_path(name), message);
  }
}

std::string TableView::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

int TableView::line_of_key(std::string_view key) const {
  const toml::node* n = table_.get(key);
  return n ? line_of(*n) : line_;
}

std::optional<double> TableView::number(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  if (!n->is_number()) {
    context_.error(line_of(*n), key_path(key), "expected a number, got " + type_name(*n));
    return std::nullopt;
  }
  const double v = *n->value<double>();
  if (!std::isfinite(v)) {
    context_.error(line_of(*n), key_path(key), "must be a finite number");
    return std::nullopt;
  }
  return v;
}

std::optional<int> TableView::integer(std::string_view key, int min, int max) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  if (!n->is_integer()) {
    context_.error(line_of(*n), key_path(key), "expected an integer, got " + type_name(*n));
    return std::nullopt;
  }
  const std::int64_t value = n->as_integer()->get();
  if (value < min || value > max) {
    context_.error(line_of(*n), key_path(key),
                   fmt::format("must be a whole number from {} to {}, got {}", min, max, value));
    return std::nullopt;
  }
  return static_cast<int>(value);
}

std::optional<bool> TableView::boolean(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  if (!n->is_boolean()) {
    context_.error(line_of(*n), key_path(key), "expected true or false, got " + type_name(*n));
    return std::nullopt;
  }
  return *n->value<bool>();
}

std::optional<std::string> TableView::string(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  if (!n->is_string()) {
    context_.error(line_of(*n), key_path(key), "expected a string, got " + type_name(*n));
    return std::nullopt;
  }
  return *n->value<std::string>();
}

std::optional<Point> to_point(ReadContext& context, const toml::node& node,
                              const std::string& key) {
  const toml::array* a = node.as_array();
  if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number()) {
    context.error(line_of(node), key, "expected a point [x, y] of two numbers");
    return std::nullopt;
  }
  const Point p{*(*a)[0].value<double>(), *(*a)[1].value<double>()};
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
    context.error(line_of(node), key, "coordinates must be finite numbers");
    return std::nullopt;
  }
  return p;
}

std::optional<Point> TableView::point(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  return to_point(context_, *n, key_path(key));
}

namespace {
std::optional<Polygon> to_points(ReadContext& context, const toml::node& node,
                                 const std::string& key) {
  const toml::array* a = node.as_array();
  if (!a) {
    context.error(line_of(node), key, "expected an array of points [[x, y], ...]");
    return std::nullopt;
  }
  Polygon out;
  bool ok = true;
  for (const toml::node& item : *a) {
    if (auto p = to_point(context, item, key)) out.push_back(*p);
    else ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}
}  // namespace

std::optional<Polygon> TableView::points(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  return to_points(context_, *n, key_path(key));
}

std::vector<std::pair<Polygon, int>> TableView::point_lists(std::string_view key) const {
  std::vector<std::pair<Polygon, int>> out;
  const toml::node* n = table_.get(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) {
    context_.error(line_of(*n), key_path(key), "expected an array of point lists");
    return out;
  }
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& item = (*a)[i];
    if (auto pts = to_points(context_, item, fmt::format("{}[{}]", key_path(key), i)))
      out.emplace_back(std::move(*pts), line_of(item));
  }
  return out;
}

const toml::table* TableView::table(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) {
    context_.error(line_of(*n), key_path(key), "expected a table, got " + type_name(*n));
    return nullptr;
  }
  return n->as_table();
}

std::vector<const toml::table*> TableView::tables(std::string_view key) const {
  std::vector<const toml::table*> out;
  const toml::node* n = table_.get(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) {
    context_.error(line_of(*n), key_path(key),
                   fmt::format("expected an array of tables ([[{}]]), got {}", key_path(key),
                               type_name(*n)));
    return out;
  }
  for (const toml::node& item : *a) {
    if (const toml::table* t = item.as_table()) out.push_back(t);
    else context_.error(line_of(item), key_path(key), "expected a table, got " + type_name(item));
  }
  return out;
}

double TableView::required_number(std::string_view key) const {
  if (!has(key)) {
    context_.error(line_, key_path(key), "required key is missing");
    return 0.0;
  }
  return number(key).value_or(0.0);
}

double TableView::number_or(std::string_view key, double fallback) const {
  if (!has(key)) {
    context_.defaults.push_back({key_path(key), format_number(fallback)});
    return fallback;
  }
  return number(key).value_or(fallback);
}

int TableView::choice(std::string_view key, const std::vector<std::string>& choices,
                      const std::string& fallback) const {
  const auto index_of = [&](const std::string& s) {
    return static_cast<int>(std::find(choices.begin(), choices.end(), s) - choices.begin());
  };
  if (!has(key)) {
    context_.defaults.push_back({key_path(key), fmt::format("\"{}\"", fallback)});
    return index_of(fallback);
  }
  const auto value = string(key);
  if (!value) return index_of(fallback);
  const int index = index_of(*value);
  if (index == static_cast<int>(choices.size())) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
    std::string message = fmt::format("\"{}\" is not one of {}", *value, list);
    const std::string nearest = suggest_nearest(*value, choices);
    if (!nearest.empty()) message += fmt::format(" (did you mean \"{}\"?)", nearest);
    context_.error(line_of_key(key), key_path(key), message);
    return index_of(fallback);
  }
  return index;
}

void TableView::require(std::string_view key, bool valid, const std::string& message) const {
  if (!valid) context_.error(line_of_key(key), key_path(key), message);
}

}  // namespace hydrodda::scenario
