#pragma once
// Whole-file writes that never leave a half-written file behind.

#include <filesystem>
#include <string_view>

namespace hydrodda::output {

// Writes `content` to a temporary file beside `path`, flushes it, then renames it over `path`
// (atomic on POSIX within one file system). Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace hydrodda::output
