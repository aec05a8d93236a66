#pragma once
// Changing values of a scenario file by key path, for parameter sweeps: the text is parsed,
// the values set, and the document written out again as TOML.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scenario/diagnostics.hpp"

namespace hydrodda::scenario {

// One change: `key` a path of dotted keys with array indices, e.g. "coupling.relaxation",
// "flow.boundary[0].head", "mechanics.traction[1].normal"; `value` a TOML value ("5", "1.5e-3",
// "\"penalty\"", "[0.0, -9.81]"), or, when it does not read as one, a string ("penalty").
struct Override {
  std::string key;
  std::string value;
};

// The scenario `text` (read from `file`) with every override applied, as TOML. A key may name
// a value that is not in the file if its table is (the reader then checks the name); every
// table and array element on the way must exist. A relative mesh.file or
// geometry.fractures_file is made absolute, so the result can be written anywhere. Comments
// are not kept. Throws ScenarioError naming `file` and the key when the text is not TOML or a
// key cannot be followed.
std::string apply_overrides(std::string_view text, const std::filesystem::path& file,
                            const std::vector<Override>& overrides);

// Diagnostics of a scenario that apply_overrides made (`made`, read as `made_file`, a file that
// may never exist) told against what the user wrote: one at a value an override set names the
// override ("--set KEY=VALUE"), any other `file` at the line of the same key in `text`.
// Diagnostics of other files (a fractures_file, a mesh file) are kept as they are.
std::vector<Diagnostic> locate_in_original(const std::vector<Diagnostic>& diagnostics, std::string_view made,
                                           const std::filesystem::path& made_file, std::string_view text,
                                           const std::filesystem::path& file, const std::vector<Override>& overrides);

}  // namespace hydrodda::scenario
