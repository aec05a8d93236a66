#pragma once
// A ParaView collection (.pvd) listing the .vtu files of a run by time, so ParaView opens the
// whole series as one animated data set. Rewritten whole (atomically) after each addition, so
// the file on disk is always complete up to the last step written.

#include <filesystem>
#include <string>
#include <vector>

namespace hydrodda::output {

class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvd_file);

  // Appends one data set: `relative_vtu` is the .vtu path relative to the .pvd's folder, `part`
  // tells apart several files of one time (e.g. 0 mesh, 1 blocks, 2 contacts). Throws
  // std::invalid_argument on a non-finite time or an empty file name.
  void add(double time, const std::string& relative_vtu, int part = 0);

  const std::filesystem::path& path() const { return path_; }
  std::size_t size() const { return entries_.size(); }
  // The XML text as last written.
  std::string text() const;

 private:
  struct Entry {
    double time;
    std::string file;
    int part;
  };
  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace hydrodda::output
