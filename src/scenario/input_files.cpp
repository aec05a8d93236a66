#include "scenario/input_files.hpp"

#include <fmt/format.h>

namespace hydrodda::scenario {

InputFileProblem inspect_input_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) return InputFileProblem::missing;
  if (std::filesystem::is_directory(status)) return InputFileProblem::folder;
  if (!std::filesystem::is_regular_file(status)) return InputFileProblem::not_regular;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec || size > max_bytes) return InputFileProblem::too_large;
  return InputFileProblem::none;
}

bool check_named_file(ReadContext& ctx, int line, const std::string& key, const std::filesystem::path& file,
                      std::uintmax_t max_bytes) {
  const std::string name = file.string();
  switch (inspect_input_file(file, max_bytes)) {
    case InputFileProblem::none: return true;
    case InputFileProblem::missing: ctx.error(line, key, fmt::format("no such file: {}", name)); break;
    case InputFileProblem::folder: ctx.error(line, key, fmt::format("{} is a folder, not a file", name)); break;
    case InputFileProblem::not_regular:
      ctx.error(line, key, fmt::format("{} is not a regular file (a device or a pipe is not read): give a file", name));
      break;
    case InputFileProblem::too_large:
      ctx.error(line, key, fmt::format("{} is larger than {} MiB, the most this key reads", name, max_bytes >> 20));
      break;
  }
  return false;
}

}  // namespace hydrodda::scenario
