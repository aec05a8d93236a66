#pragma once
// Files a scenario reads: the scenario itself and the files its keys name (geometry.fractures_file,
// mesh.file). Only a regular file of bounded size is read: a device such as /dev/zero would be
// read without end, a FIFO blocks until something writes to it, a folder reads as empty.

#include <cstdint>
#include <filesystem>
#include <string>

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// The largest fractures file read: some 800,000 rows of x1,y1,x2,y2 at full precision, more
// traces than the cutting handles (a joint set is refused beyond 100,000).
inline constexpr std::uintmax_t kMaxFracturesFileBytes = std::uintmax_t{64} << 20;
// The largest mesh file read: an ASCII .msh of some ten million triangles, beyond what a run
// holds in memory on most machines (1,200 bytes a triangle, docs/scenario.md).
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{1} << 30;

enum class InputFileProblem { none, missing, folder, not_regular, too_large };

// What stands in the way of reading `file` as an input of at most `max_bytes`, found without
// opening it (a FIFO is not waited on).
InputFileProblem inspect_input_file(const std::filesystem::path& file, std::uintmax_t max_bytes);

// Whether the file `key` names (on `line`) can be read; when not, an error naming the key says why.
bool check_named_file(ReadContext& context, int line, const std::string& key, const std::filesystem::path& file,
                      std::uintmax_t max_bytes);

}  // namespace hydrodda::scenario
