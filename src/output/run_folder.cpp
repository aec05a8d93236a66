#include "output/run_folder.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "output/atomic_file.hpp"

namespace hydrodda::output {

namespace fs = std::filesystem;

void RunFolder::check_available(const fs::path& directory, ExistingFolder policy) {
  std::error_code ec;
  if (!fs::exists(directory, ec)) return;
  if (!fs::is_directory(directory, ec))
    throw RunFolderError(fmt::format("{} exists and is not a folder", directory.string()));
  if (policy == ExistingFolder::Refuse && !fs::is_empty(directory, ec))
    throw RunFolderError(fmt::format(
        "{} already holds files; choose another folder with -o, or pass --overwrite to "
        "replace the results in it",
        directory.string()));
}

RunFolder::RunFolder(fs::path directory, ExistingFolder policy) : directory_(std::move(directory)) {
  check_available(directory_, policy);
  std::error_code ec;
  if (fs::is_directory(directory_, ec)) return;
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
