#include "sweep/cases.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace hydrodda::sweep {

namespace {

// Splits at commas outside brackets, braces and quotes.
std::vector<std::string> split_values(const std::string& list) {
  std::vector<std::string> values;
  std::string current;
  int depth = 0;
  char quote = 0;
  for (char c : list) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      values.push_back(current);
      current.clear();
      continue;
    }
    current += c;
  }
  values.push_back(current);
  return values;
}

std::string trim(const std::string& s) {
  const std::size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// The same key twice would run with its last value only and give sweep.csv two columns of
// that name: refused.
void check_distinct_keys(const std::vector<SweepAxis>& axes) {
  for (std::size_t i = 0; i < axes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (axes[i].key == axes[j].key)
        throw std::invalid_argument(fmt::format("--set {}: the key is given twice; list all its values in one --set "
                                                "({}=V1,V2,...)",
                                                axes[i].key, axes[i].key));
}

// Refuses a sweep of more than kMaxSweepCases cases, before any is built: `count` of them, the
// product of the lists' lengths (their common length with `zipped`).
void check_case_count(const std::vector<SweepAxis>& axes, bool zipped) {
  double count = axes.empty() ? 1.0 : static_cast<double>(axes[0].values.size());
  std::string factors;
  for (std::size_t k = 0; k < axes.size(); ++k) {
    if (!zipped && k > 0) count *= static_cast<double>(axes[k].values.size());
    factors += fmt::format("{}--set {}: {} value(s)", k == 0 ? "" : zipped ? ", " : " × ", axes[k].key,
                           axes[k].values.size());
  }
  if (count <= static_cast<double>(kMaxSweepCases)) return;
  throw std::invalid_argument(fmt::format(
      "the sweep has {} cases ({}{}); at most {} run in one sweep: split it into several with fewer values",
      count < 1e15 ? fmt::format("{:.0f}", count) : fmt::format("{:.3g}", count), factors,
      zipped ? ", taken together with --zip" : "", kMaxSweepCases));
}

}  // namespace

SweepAxis parse_sweep_axis(const std::string& option) {
  const std::size_t equals = option.find('=');
  if (equals == std::string::npos)
    throw std::invalid_argument(fmt::format("--set {}: expected KEY=V1,V2,...", option));
  SweepAxis axis{trim(option.substr(0, equals)), {}};
  if (axis.key.empty()) throw std::invalid_argument(fmt::format("--set {}: the key is empty", option));
  for (const std::string& value : split_values(option.substr(equals + 1))) {
    axis.values.push_back(trim(value));
    if (axis.values.back().empty())
      throw std::invalid_argument(fmt::format("--set {}: an empty value in the list", option));
  }
  return axis;
}

std::vector<std::vector<scenario::Override>> enumerate_cases(const std::vector<SweepAxis>& axes) {
  check_distinct_keys(axes);
  check_case_count(axes, false);
  std::vector<std::vector<scenario::Override>> cases{{}};
  for (const SweepAxis& axis : axes) {
    std::vector<std::vector<scenario::Override>> longer;
    for (const auto& partial : cases)
      for (const std::string& value : axis.values) {
        longer.push_back(partial);
        longer.back().push_back({axis.key, value});
      }
    cases = std::move(longer);
  }
  return cases;
}

std::vector<std::vector<scenario::Override>> zip_cases(const std::vector<SweepAxis>& axes) {
  check_distinct_keys(axes);
  std::vector<std::vector<scenario::Override>> cases;
  if (axes.empty()) return {{}};
  for (const SweepAxis& axis : axes)
    if (axis.values.size() != axes[0].values.size())
      throw std::invalid_argument("--zip: --set " + axes[0].key + " has " + std::to_string(axes[0].values.size()) +
                                  " value(s) but --set " + axis.key + " has " + std::to_string(axis.values.size()) +
                                  "; zipped keys need as many values each");
  check_case_count(axes, true);
  for (std::size_t i = 0; i < axes[0].values.size(); ++i) {
    cases.emplace_back();
    for (const SweepAxis& axis : axes) cases.back().push_back({axis.key, axis.values[i]});
  }
  return cases;
}

}  // namespace hydrodda::sweep
