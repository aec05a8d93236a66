#pragma once
// The run folder: where a run writes everything, and nowhere else.

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string_view>

#include "output/atomic_file.hpp"

namespace hydrodda::output {

// What to do when the run folder already holds files.
enum class ExistingFolder {
  Refuse,     // refused, so that no earlier result is lost
  Overwrite,  // files of the same name are replaced, other files left alone
  Continue,   // the folder of a run continued (resume): its own files, written on
};

class RunFolder {
 public:
  // Creates the folder (and its parents) on demand, or takes it as `policy` says. Overwrite is
  // refused for the current folder or one that holds it (a user's own scenario.toml or
  // summary.json there would be replaced), and for a folder whose figures/ is a symbolic link
  // (nothing is written outside the folder).
  RunFolder(std::filesystem::path directory, ExistingFolder policy);

  const std::filesystem::path& path() const { return directory_; }
  std::filesystem::path file(std::string_view name) const { return directory_ / name; }
  // The folder `name` inside this one, created when missing; RunFolderError when something
  // other than a folder is in the way, a symbolic link included (it would lead outside).
  std::filesystem::path subfolder(std::string_view name) const;
  // The figures/ subfolder, created on first use.
  std::filesystem::path figures() const { return subfolder("figures"); }

  // Writes a file in the folder atomically (temporary name, then rename), flushed to the disk
  // first when durability_of(name) says so; RunFolderError naming the file when it cannot.
  void write(std::string_view name, std::string_view content) const;
  // The same for a file made in pieces: `fill` writes them into the file, which is committed
  // after it returns.
  void write_with(std::string_view name, const std::function<void(AtomicFile&)>& fill) const;

  // What a power cut must not take (docs/output.md, "Durability"): the files a resume reads
  // (checkpoint.bin and the scenario.toml it was made from) and the run's verdict
  // (summary.json) are durable; the rest (fields, tables, figures), which the run makes from
  // its state, only atomic.
  static Durability durability_of(std::string_view name);
  // Flushes the folder's own entries to the disk (fsync of the folder), so that the durable
  // files renamed into it survive a power cut under their names: once at the run's end.
  // RunFolderError naming the folder when it cannot.
  void sync() const;

 private:
  // Throws RunFolderError when the folder could not be used under `policy`; creates nothing.
  static void check_available(const std::filesystem::path& directory, ExistingFolder policy);
  // Throws RunFolderError when overwriting `directory` would replace files a run did not write.
  static void check_overwritable(const std::filesystem::path& directory);
  // Throws RunFolderError when no file can be created in the folder.
  static void check_writable(const std::filesystem::path& directory);

  std::filesystem::path directory_;
};

// Thrown when the folder exists and holds files, cannot be created, or cannot be written.
class RunFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hydrodda::output
