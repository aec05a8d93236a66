#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace hydrodda::output {

namespace {
[[noreturn]] void fail(const std::filesystem::path& path, const char* what) {
  throw std::runtime_error(fmt::format("cannot write {}: {}: {}", path.string(), what,
                                       std::strerror(errno)));
}
// A test hook: HYDRODDA_TEST_FULL_DISK=NAME makes every write of a file named NAME fail as on a
// full disk, so that tests reach what a full disk does to a run without filling one.
bool full_disk_for(const std::filesystem::path& path) {
  const char* name = std::getenv("HYDRODDA_TEST_FULL_DISK");
  return name && *name && path.filename() == name;
}
std::atomic<long long> flushes{0};
}  // namespace

long long disk_flushes() { return flushes.load(); }

bool flush_to_disk(int fd) {
  ++flushes;
  return ::fsync(fd) == 0;
}

AtomicFile::AtomicFile(const std::filesystem::path& path, Durability durability)
    : path_(path), temporary_(path), durability_(durability), full_disk_(full_disk_for(path)) {
  // The temporary name carries the process id so that two runs never share one.
  temporary_ += fmt::format(".tmp.{}", ::getpid());
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail(temporary_, "open");
}

AtomicFile::~AtomicFile() {
  if (fd_ < 0) return;
  ::close(fd_);
  ::unlink(temporary_.c_str());
}

void AtomicFile::write(std::string_view bytes) {
  write_at(size_, bytes);
  size_ += bytes.size();
}

void AtomicFile::write_at(std::size_t position, std::string_view bytes) {
  if (fd_ < 0) throw std::logic_error("AtomicFile: a write after commit");
  if (full_disk_ && !bytes.empty()) {
    errno = ENOSPC;
    fail(temporary_, "write");
  }
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::pwrite(fd_, bytes.data() + written, bytes.size() - written,
                               static_cast<off_t>(position + written));
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(temporary_, "write");
    }
    written += static_cast<std::size_t>(n);
  }
}

void AtomicFile::commit() {
  if (fd_ < 0) throw std::logic_error("AtomicFile::commit twice");
  const int fd = fd_;
  fd_ = -1;
  const bool synced = durability_ == Durability::atomic || flush_to_disk(fd);
  const bool closed = ::close(fd) == 0;
  if (!synced || !closed) {
    ::unlink(temporary_.c_str());
    fail(temporary_, "flush");
  }
  if (::rename(temporary_.c_str(), path_.c_str()) != 0) {
    ::unlink(temporary_.c_str());
    fail(path_, "rename");
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content, Durability durability) {
  AtomicFile file(path, durability);
  file.write(content);
  file.commit();
}

}  // namespace hydrodda::output
