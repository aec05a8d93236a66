#pragma once
// Reading a scenario file (TOML) into a validated Scenario.

#include <cstdint>
#include <filesystem>
#include <string_view>

#include "scenario/scenario.hpp"

namespace hydrodda::scenario {

// The largest scenario file read: far above any real one, far below what would exhaust memory.
inline constexpr std::uintmax_t kMaxScenarioBytes = std::uintmax_t{16} << 20;

// Reads and validates a scenario file (a regular file of at most kMaxScenarioBytes). Every problem found is collected; if there is any, a
// ScenarioError listing them all (file:line: key: message) is thrown. Nothing is written.
Scenario read_scenario(const std::filesystem::path& file);

// The same from text, for tests and tools; `file` names the source in messages and is the
// base for relative paths.
Scenario parse_scenario(std::string_view text, const std::filesystem::path& file);

}  // namespace hydrodda::scenario
