#include "scenario/overrides.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>

#include "scenario/diagnostics.hpp"

namespace hydrodda::scenario {

namespace {

// One step of a key path: a key, then any number of array indices ("boundary[0]").
struct PathStep {
  std::string key;
  std::vector<std::size_t> indices;
};

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& key, const std::string& message) {
  throw ScenarioError({{file.string(), 0, key, message}});
}

std::vector<PathStep> split_key_path(const std::filesystem::path& file, const std::string& path) {
  std::vector<PathStep> steps;
  std::stringstream parts(path);
  std::string part;
  while (std::getline(parts, part, '.')) {
    PathStep step;
    const std::size_t bracket = part.find('[');
    step.key = part.substr(0, bracket);
    if (step.key.empty()) fail(file, path, "expected a key path such as flow.boundary[0].head");
    for (std::size_t at = bracket; at != std::string::npos; at = part.find('[', at)) {
      const std::size_t close = part.find(']', at);
      std::size_t index = 0;
      const char* first = part.data() + at + 1;
      const char* last = part.data() + (close == std::string::npos ? part.size() : close);
      const auto [end, ec] = std::from_chars(first, last, index);
      if (close == std::string::npos || ec != std::errc{} || end != last)
        fail(file, path, fmt::format("'{}' is not a key with array indices such as boundary[0]", part));
      step.indices.push_back(index);
      at = close + 1;
      if (at < part.size() && part[at] != '[') fail(file, path, fmt::format("unexpected text after ']' in '{}'", part));
    }
    steps.push_back(std::move(step));
  }
  if (path.empty() || path.back() == '.' || steps.empty())
    fail(file, path, "expected a key path such as flow.boundary[0].head");
  return steps;
}

// A number written in full that TOML cannot hold: a whole number beyond 64 bits (2^70 =
// 1180591620717411303424) or a decimal beyond a double's range (3e400).
bool is_number_out_of_range(std::string_view text) {
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  const char* last = text.data() + text.size();
  std::int64_t whole = 0;
  double decimal = 0.0;
  const auto as_whole = std::from_chars(text.data(), last, whole);
  const auto as_decimal = std::from_chars(text.data(), last, decimal);
  return (as_whole.ec == std::errc::result_out_of_range && as_whole.ptr == last) ||
         (as_decimal.ec == std::errc::result_out_of_range && as_decimal.ptr == last);
}

// The value text as TOML; text that does not read as a TOML value is taken as a string.
toml::table parse_value(const Override& o) {
  const std::string& value = o.value;
  try {
    toml::table holder = toml::parse("v = " + value);
    if (holder.size() == 1 && holder.contains("v")) return holder;
  } catch (const toml::parse_error&) {
    if (is_number_out_of_range(value))
      throw ScenarioError({{fmt::format("--set {}={}", o.key, value), 0, o.key,
                            fmt::format("{} is out of range: a number lies within ±1.8e308, a whole number within "
                                        "±9.2e18 (2^63)", value)}});
  }
  toml::table holder;
  holder.insert("v", value);
  return holder;
}

// Follows `indices` into the arrays under `node`; the element reached, with its name.
toml::node* follow_indices(const std::filesystem::path& file, const std::string& full_key, toml::node* node,
                           std::string& name, const std::vector<std::size_t>& indices) {
  for (std::size_t index : indices) {
    toml::array* array = node->as_array();
    if (!array) fail(file, full_key, fmt::format("{} is not an array", name));
    if (index >= array->size())
      fail(file, full_key, fmt::format("{} has {} element(s); index {} is out of range", name, array->size(), index));
    name += fmt::format("[{}]", index);
    node = array->get(index);
  }
  return node;
}

// Top-level tables of settings only, each optional: a scenario without one runs on its
// defaults, so an override of one of its keys makes it. The others ([mechanics], [flow],
// [geometry], ...) say what is run; one made by an override would change the kind of run.
bool is_settings_table(const std::string& key) {
  return key == "coupling" || key == "output" || key == "mesh" || key == "joint";
}

void apply_override(const std::filesystem::path& file, toml::table& document, const Override& o) {
  const std::vector<PathStep> steps = split_key_path(file, o.key);
  toml::table* table = &document;
  std::string name;
  for (std::size_t s = 0; s + 1 < steps.size(); ++s) {
    name += (name.empty() ? "" : ".") + steps[s].key;
    toml::node* node = table->get(steps[s].key);
    if (!node && s == 0 && steps[s].indices.empty() && is_settings_table(steps[s].key))
      node = table->insert(steps[s].key, toml::table{}).first->second.as_table();
    if (!node) fail(file, o.key, fmt::format("the scenario has no '{}' to follow", name));
    node = follow_indices(file, o.key, node, name, steps[s].indices);
    table = node->as_table();
    if (!table) fail(file, o.key, fmt::format("{} is not a table", name));
  }
  toml::table value = parse_value(o);
  toml::node& new_value = *value.get("v");
  const PathStep& last = steps.back();
  toml::node* old_value = table->get(last.key);
  // A whole number given for a value written as a decimal stays a decimal.
  const auto keep_float = [&](toml::node& old, toml::node& replacement) -> toml::node& {
    if (old.is_floating_point() && replacement.is_integer())
      value.insert_or_assign("v", static_cast<double>(*replacement.value<long long>()));
    return *value.get("v");
  };
  if (last.indices.empty()) {
    table->insert_or_assign(last.key, std::move(old_value ? keep_float(*old_value, new_value) : new_value));
    return;
  }
  name += (name.empty() ? "" : ".") + last.key;
  if (!old_value) fail(file, o.key, fmt::format("the scenario has no '{}' to follow", name));
  const std::vector<std::size_t> parents(last.indices.begin(), last.indices.end() - 1);
  toml::array* array = follow_indices(file, o.key, old_value, name, parents)->as_array();
  if (!array) fail(file, o.key, fmt::format("{} is not an array", name));
  const std::size_t index = last.indices.back();
  if (index >= array->size())
    fail(file, o.key, fmt::format("{} has {} element(s); index {} is out of range", name, array->size(), index));
  toml::node& replacement = keep_float(*array->get(index), new_value);
  array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(index), std::move(replacement));
}

// The key path of every value and table of `node` by the line it starts on; where several start
// on one line (an inline array and its elements), the shortest.
void map_lines(const toml::node& node, const std::string& path, std::map<int, std::string>& path_of_line) {
  const int line = static_cast<int>(node.source().begin.line);
  if (line > 0 && !path.empty()) {
    const auto [at, inserted] = path_of_line.try_emplace(line, path);
    if (!inserted && path.size() < at->second.size()) at->second = path;
  }
  if (const toml::table* table = node.as_table()) {
    for (auto&& [key, value] : *table)
      map_lines(value, path.empty() ? std::string(key.str()) : fmt::format("{}.{}", path, key.str()), path_of_line);
  } else if (const toml::array* array = node.as_array()) {
    for (std::size_t i = 0; i < array->size(); ++i) map_lines(*array->get(i), fmt::format("{}[{}]", path, i), path_of_line);
  }
}

// `path` is `key` or lies under it ("flow.boundary[0].head" under "flow.boundary[0]").
bool lies_under(const std::string& path, const std::string& key) {
  return path.starts_with(key) && (path.size() == key.size() || path[key.size()] == '.' || path[key.size()] == '[');
}

// "flow.boundary[0].head" as a diagnostic names it: "flow.boundary.head".
std::string without_indices(const std::string& key) {
  std::string out;
  bool in_index = false;
  for (char c : key) {
    if (c == '[') in_index = true;
    if (!in_index) out += c;
    if (c == ']') in_index = false;
  }
  return out;
}

// The line of `path` in `document`, or of the nearest table or array above it that is there; 0
// when none is.
int line_in(const toml::table& document, std::string path) {
  while (!path.empty()) {
    if (const toml::node* node = toml::at_path(document, path).node()) return static_cast<int>(node->source().begin.line);
    const std::size_t cut = path.find_last_of(".[");
    path = cut == std::string::npos ? std::string() : path.substr(0, cut);
  }
  return 0;
}

toml::table parse_or_empty(std::string_view text) {
  try {
    return toml::parse(text);
  } catch (const toml::parse_error&) {
    return {};
  }
}

}  // namespace

std::vector<Diagnostic> locate_in_original(const std::vector<Diagnostic>& diagnostics, std::string_view made,
                                           const std::filesystem::path& made_file, std::string_view text,
                                           const std::filesystem::path& file, const std::vector<Override>& overrides) {
  std::map<int, std::string> path_of_line;
  map_lines(parse_or_empty(made), "", path_of_line);
  const toml::table original = parse_or_empty(text);
  std::vector<Diagnostic> located;
  for (Diagnostic d : diagnostics) {
    if (d.file != made_file.string()) {
      located.push_back(std::move(d));
      continue;
    }
    const auto at = path_of_line.find(d.line);
    const std::string path = d.line > 0 && at != path_of_line.end() ? at->second : std::string();
    const auto set_by = std::find_if(overrides.begin(), overrides.end(), [&](const Override& o) {
      const bool names_it = !d.key.empty() && without_indices(o.key) == d.key;
      // At the value the override set, or named and cited at a table that holds it.
      return path.empty() ? names_it : lies_under(path, o.key) || (names_it && lies_under(o.key, path));
    });
    if (set_by != overrides.end()) {
      d.file = fmt::format("--set {}={}", set_by->key, set_by->value);
      d.line = 0;
    } else {
      d.file = file.string();
      d.line = path.empty() ? 0 : line_in(original, path);
    }
    located.push_back(std::move(d));
  }
  return located;
}

std::string apply_overrides(std::string_view text, const std::filesystem::path& file,
                            const std::vector<Override>& overrides) {
  toml::table document;
  try {
    document = toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    throw ScenarioError({{file.string(), static_cast<int>(e.source().begin.line), "",
                          "malformed TOML: " + std::string(e.description())}});
  }
  for (const Override& o : overrides) apply_override(file, document, o);
  for (const auto& [section, key] : {std::pair{"mesh", "file"}, std::pair{"geometry", "fractures_file"}})
    if (toml::table* table = document[section].as_table())
      if (const auto named = table->get_as<std::string>(key)) {
        const std::filesystem::path path(named->get());
        if (path.is_relative()) table->insert_or_assign(key, std::filesystem::absolute(file.parent_path() / path).string());
      }
  std::ostringstream out;
  out << toml::toml_formatter(document) << '\n';
  return out.str();
}

}  // namespace hydrodda::scenario
