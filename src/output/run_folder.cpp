#include "output/run_folder.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "output/atomic_file.hpp"

namespace hydrodda::output {

namespace fs = std::filesystem;

RunFolder::RunFolder(fs::path directory, ExistingFolder policy) : directory_(std::move(directory)) {
  std::error_code ec;
  if (fs::exists(directory_, ec)) {
    if (!fs::is_directory(directory_, ec))
      throw RunFolderError(fmt::format("{} exists and is not a folder", directory_.string()));
    if (policy == ExistingFolder::Refuse && !fs::is_empty(directory_, ec))
      throw RunFolderError(fmt::format(
          "{} already holds files; choose another folder with -o, or pass --overwrite to "
          "replace the results in it",
          directory_.string()));
    return;
  }
  fs::create_directories(directory_, ec);
  if (ec)
    throw RunFolderError(fmt::format("cannot create {}: {}", directory_.string(), ec.message()));
}

fs::path RunFolder::figures() const {
  const fs::path dir = directory_ / "figures";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw RunFolderError(fmt::format("cannot create {}: {}", dir.string(), ec.message()));
  return dir;
}

void RunFolder::write(std::string_view name, std::string_view content) const {
  write_file_atomically(directory_ / name, content);
}

}  // namespace hydrodda::output
