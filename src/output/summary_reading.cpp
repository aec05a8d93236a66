#include "output/summary_reading.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "output/csv_table.hpp"

namespace hydrodda::output {

namespace {

using nlohmann::json;

// Follows a dotted path; a part that is a whole number indexes an array.
const json* find_value(const json& root, const std::string& path) {
  const json* node = &root;
  std::stringstream parts(path);
  std::string part;
  while (std::getline(parts, part, '.')) {
    if (node->is_object()) {
      const auto it = node->find(part);
      if (it == node->end()) return nullptr;
      node = &*it;
    } else if (node->is_array()) {
      std::size_t index = 0, used = 0;
      try {
        index = std::stoul(part, &used);
      } catch (const std::exception&) {
        return nullptr;
      }
      if (used != part.size() || index >= node->size()) return nullptr;
      node = &(*node)[index];
    } else {
      return nullptr;
    }
  }
  return node;
}

std::optional<std::string> format_cell(const json& value) {
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer()) return CsvTable::cell(value.get<long long>());
  if (value.is_number()) return CsvTable::cell(value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  return std::nullopt;  // objects, arrays and null (a NaN written by the run)
}

}  // namespace

namespace {

std::vector<std::optional<std::string>> values_at(const json& root, const std::vector<std::string>& paths) {
  std::vector<std::optional<std::string>> values;
  for (const std::string& path : paths) {
    const json* value = find_value(root, path);
    values.push_back(value ? format_cell(*value) : std::nullopt);
  }
  return values;
}

}  // namespace

std::vector<std::optional<std::string>> read_summary_values(const std::filesystem::path& file,
                                                            const std::vector<std::string>& paths) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(fmt::format("cannot open {}", file.string()));
  json root;
  try {
    root = json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("{} is not valid JSON: {}", file.string(), e.what()));
  }
  return values_at(root, paths);
}

std::vector<std::optional<std::string>> summary_values(std::string_view text, const std::vector<std::string>& paths) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("a summary that is not valid JSON: {}", e.what()));
  }
  return values_at(root, paths);
}

}  // namespace hydrodda::output
