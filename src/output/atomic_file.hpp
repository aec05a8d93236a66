#pragma once
// Whole-file writes that never leave a half-written file behind.

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace hydrodda::output {

// How far a committed file is kept (docs/output.md, "Durability").
enum class Durability {
  // Its bytes flushed to the disk (fsync) before the rename: once the folder's entries are
  // flushed too (RunFolder::sync, or the file system's next journal commit), it survives a
  // power cut whole.
  durable,
  // Renamed without flushing: whole or as it was if the program dies, but a power cut before
  // the system writes it back (Linux: within some 30 s) may leave it empty, as it was, or absent.
  atomic,
};

// The fsync calls this process made through AtomicFile and RunFolder::sync (a statistic for
// tests and benchmarks).
long long disk_flushes();
// fsync of `fd`, counted; false on failure with errno set.
bool flush_to_disk(int fd);

// A file written in pieces to a temporary file beside `path`, then flushed and renamed over
// `path` by commit() (atomic on POSIX within one file system): a large file (a fluid field of
// a million triangles) is written as its parts are made, never held whole in memory. Not
// committed, the temporary file is removed and `path` is left as it was. Flushed to the disk
// before its rename unless `durability` says otherwise. Throws std::runtime_error naming the
// path on failure.
class AtomicFile {
 public:
  explicit AtomicFile(const std::filesystem::path& path, Durability durability = Durability::durable);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends `bytes`.
  void write(std::string_view bytes);
  // Overwrites bytes already written, from `position` on (a header filled in last).
  void write_at(std::size_t position, std::string_view bytes);
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  std::size_t size_ = 0;  // bytes appended so far
  Durability durability_;
  bool full_disk_ = false;  // writes fail as on a full disk (HYDRODDA_TEST_FULL_DISK, for tests)
};

// The whole `content` through an AtomicFile.
void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                           Durability durability = Durability::durable);

}  // namespace hydrodda::output
