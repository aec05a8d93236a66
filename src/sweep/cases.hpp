#pragma once
// The cases of a parameter sweep: every combination of the values given with --set, or
// (--zip) the values taken together.

#include <string>
#include <vector>

#include "scenario/overrides.hpp"

namespace hydrodda::sweep {

// One swept key and its values, from "KEY=V1,V2,...".
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

// Parses "KEY=V1,V2,..."; commas inside brackets or quotes do not split ("g=[0,-9.81],[0,-5]").
// Throws std::invalid_argument with a message naming the option when it is malformed.
SweepAxis parse_sweep_axis(const std::string& option);

// The most cases one sweep runs. Each is checked, and its scenario file held, before any runs
// (40,000 took a minute to prepare, 10^9 exhausted the memory): a longer sweep is split.
inline constexpr std::size_t kMaxSweepCases = 10000;

// The Cartesian product of the axes' values, the first axis varying slowest: case i sets
// axes[k].key to its value in each. Both this and zip_cases throw std::invalid_argument when
// a key is given twice, and before building any case when there would be more than
// kMaxSweepCases, naming the keys whose values multiply to that.
std::vector<std::vector<scenario::Override>> enumerate_cases(const std::vector<SweepAxis>& axes);

// The axes' values taken together (--zip): case i sets every axis's key to its i-th value, so
// that keys which must move together (the two ends of a couple) are swept as one. Throws
// std::invalid_argument naming the axes when they do not all have the same number of values.
std::vector<std::vector<scenario::Override>> zip_cases(const std::vector<SweepAxis>& axes);

}  // namespace hydrodda::sweep
