#include "output/run_folder.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "output/atomic_file.hpp"

namespace hydrodda::output {

namespace fs = std::filesystem;

void RunFolder::check_available(const fs::path& directory, ExistingFolder policy) {
  if (directory.empty()) throw RunFolderError("no run folder given (an empty path)");
  std::error_code ec;
  if (!fs::exists(directory, ec)) return;
  if (!fs::is_directory(directory, ec))
    throw RunFolderError(fmt::format("{} exists and is not a folder", directory.string()));
  if (policy == ExistingFolder::Refuse && !fs::is_empty(directory, ec))
    throw RunFolderError(fmt::format(
        "{} already holds files; choose another folder with -o, or pass --overwrite to "
        "replace the results in it",
        directory.string()));
  if (policy == ExistingFolder::Overwrite) check_overwritable(directory);
}

namespace {
// `directory` is the current folder or holds it.
bool holds_current_folder(const fs::path& directory) {
  std::error_code ec;
  const fs::path here = fs::current_path(ec);
  const fs::path folder = fs::canonical(directory, ec);
  if (ec || here.empty()) return false;
  const auto [end_of_folder, in_here] = std::mismatch(folder.begin(), folder.end(), here.begin(), here.end());
  return end_of_folder == folder.end();
}
}  // namespace

void RunFolder::check_overwritable(const fs::path& directory) {
  if (holds_current_folder(directory))
    throw RunFolderError(fmt::format(
        "--overwrite is refused for {}: it is the current folder or holds it, and files of yours named as a "
        "run's files (scenario.toml, summary.json, figures/) would be replaced; give the run a folder of its own",
        directory.string()));
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(directory / "figures", ec)))
    throw RunFolderError(fmt::format("{} is a symbolic link: a run writes only inside its folder; remove the link "
                                     "or choose another folder",
                                     (directory / "figures").string()));
}

RunFolder::RunFolder(fs::path directory, ExistingFolder policy) : directory_(std::move(directory)) {
  check_available(directory_, policy);
  std::error_code ec;
  if (!fs::is_directory(directory_, ec)) {
    if (fs::is_symlink(fs::symlink_status(directory_, ec)))  // create_directories said only "File exists"
      throw RunFolderError(fmt::format("cannot create {}: it is a symbolic link to {}, which does not exist",
                                       directory_.string(), fs::read_symlink(directory_, ec).string()));
    fs::create_directories(directory_, ec);
    if (ec) throw RunFolderError(fmt::format("cannot create {}: {}", directory_.string(), ec.message()));
  }
  check_writable(directory_);
}

void RunFolder::check_writable(const fs::path& directory) {
  // Tried rather than predicted from permission bits: ACLs, read-only mounts and root all
  // decide differently.
  const fs::path probe = directory / fmt::format(".write-test.{}", ::getpid());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw RunFolderError(fmt::format("cannot write in {}: {}", directory.string(), std::strerror(errno)));
  ::close(fd);
  ::unlink(probe.c_str());
}

fs::path RunFolder::subfolder(std::string_view name) const {
  const fs::path dir = directory_ / name;
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (fs::is_symlink(status))
    throw RunFolderError(fmt::format("cannot write in {}: it is a symbolic link, and a run writes only inside its "
                                     "folder; remove the link",
                                     dir.string()));
  if (fs::exists(status) && !fs::is_directory(status))
    throw RunFolderError(fmt::format("cannot create {}: a file of that name is in the way", dir.string()));
  fs::create_directory(dir, ec);
  if (ec) throw RunFolderError(fmt::format("cannot create {}: {}", dir.string(), ec.message()));
  return dir;
}

void RunFolder::write(std::string_view name, std::string_view content) const {
  write_with(name, [&](AtomicFile& file) { file.write(content); });
}

void RunFolder::write_with(std::string_view name, const std::function<void(AtomicFile&)>& fill) const {
  const fs::path path = directory_ / name;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw RunFolderError(fmt::format("cannot write {}: a folder of that name is in the way", path.string()));
  try {
    AtomicFile file(path, durability_of(name));
    fill(file);
    file.commit();
  } catch (const std::runtime_error& e) {
    throw RunFolderError(e.what());
  }
}

Durability RunFolder::durability_of(std::string_view name) {
  return name == "checkpoint.bin" || name == "scenario.toml" || name == "summary.json" ? Durability::durable
                                                                                       : Durability::atomic;
}

void RunFolder::sync() const {
  const int fd = ::open(directory_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw RunFolderError(fmt::format("cannot flush {}: {}", directory_.string(), std::strerror(errno)));
  const bool flushed = flush_to_disk(fd);
  const int error = errno;
  ::close(fd);
  if (!flushed) throw RunFolderError(fmt::format("cannot flush {}: {}", directory_.string(), std::strerror(error)));
}

}  // namespace hydrodda::output
