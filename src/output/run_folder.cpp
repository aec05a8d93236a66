#include "output/run_folder.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
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

fs::path RunFolder::figures() const {
  const fs::path dir = directory_ / "figures";
  std::error_code ec;
  fs::create_directories(dir, ec);
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
    AtomicFile file(path);
    fill(file);
    file.commit();
  } catch (const std::runtime_error& e) {
    throw RunFolderError(e.what());
  }
}

}  // namespace hydrodda::output
