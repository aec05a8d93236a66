#pragma once
// Reading values back from a run's summary.json, for tools that gather many runs (sweeps).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hydrodda::output {

// For each dotted path into summary.json (e.g. "flow.regions.core.effective_conductivity",
// "blocks.0.rotation"), the value as a CSV cell: numbers in full precision, true/false,
// strings as they are; nullopt where the path leads nowhere or to an object or array.
// Throws std::runtime_error naming the file when it cannot be read or is not JSON.
std::vector<std::optional<std::string>> read_summary_values(const std::filesystem::path& file,
                                                            const std::vector<std::string>& paths);
// The same from summary.json's text (format_summary's); std::runtime_error when it is not JSON.
std::vector<std::optional<std::string>> summary_values(std::string_view text, const std::vector<std::string>& paths);

}  // namespace hydrodda::output
