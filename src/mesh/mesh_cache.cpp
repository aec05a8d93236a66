#include "mesh/mesh_cache.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace hydrodda::mesh {

namespace fs = std::filesystem;

namespace {

// 2: a checksum of the whole entry after its mesh.
constexpr char kMagic[] = "hydrodda cached mesh 2\n";

std::string exact(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%a", value);
  return text;
}

std::string point_text(Point p) { return exact(p.x) + " " + exact(p.y); }

// FNV-1a, 64 bits, fed in pieces: a file name for a key, and the checksum of an entry, which
// tells a mesh damaged on disk (a node moved by one flipped bit) from the mesh that was stored.
// Written here as such a hash needs no library.
class Fnv1a {
 public:
  void add(const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      hash_ ^= bytes[i];
      hash_ *= 1099511628211ull;
    }
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

std::uint64_t fnv1a(const std::string& text) {
  Fnv1a hash;
  hash.add(text.data(), text.size());
  return hash.value();
}

// An entry that cannot be used: cut short, damaged, or not a cached mesh of this format.
class BadEntry : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Writer {
 public:
  explicit Writer(std::ofstream& out) : out_(out) {}
  void bytes(const void* data, std::size_t n) {
    hash_.add(data, n);
    out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
  }
  void count(std::size_t n) {
    const std::uint64_t v = n;
    bytes(&v, sizeof v);
  }
  void text(const std::string& s) {
    count(s.size());
    bytes(s.data(), s.size());
  }
  template <class T>
  void array(const std::vector<T>& v) {
    count(v.size());
    bytes(v.data(), v.size() * sizeof(T));
  }
  // The checksum of every byte so far, last in the file.
  void checksum() {
    const std::uint64_t sum = hash_.value();
    out_.write(reinterpret_cast<const char*>(&sum), sizeof sum);
  }

 private:
  std::ofstream& out_;
  Fnv1a hash_;
};

class Reader {
 public:
  Reader(std::ifstream& in, const fs::path& file) : in_(in), file_(file), left_(fs::file_size(file)) {}
  void bytes(void* data, std::size_t n) {
    read(data, n);
    hash_.add(data, n);
  }
  std::size_t count(std::size_t item_size = 1) {
    std::uint64_t v = 0;
    bytes(&v, sizeof v);
    if (v > left_ / item_size) fail("is cut short");
    return static_cast<std::size_t>(v);
  }
  std::string text() {
    std::string s(count(), '\0');
    bytes(s.data(), s.size());
    return s;
  }
  template <class T>
  std::vector<T> array() {
    std::vector<T> v(count(sizeof(T)));
    bytes(v.data(), v.size() * sizeof(T));
    return v;
  }
  // The stored checksum, which must be that of every byte read and the file's last bytes.
  void check_sum() {
    std::uint64_t stored = 0;
    read(&stored, sizeof stored);
    if (left_ != 0 || stored != hash_.value()) fail("is damaged: its checksum does not match its contents");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw BadEntry("cached mesh '" + file_.string() + "' " + what);
  }

 private:
  void read(void* data, std::size_t n) {
    if (n > left_ || !in_.read(static_cast<char*>(data), static_cast<std::streamsize>(n))) fail("is cut short");
    left_ -= n;
  }

  std::ifstream& in_;
  fs::path file_;
  std::uintmax_t left_;
  Fnv1a hash_;
};

// An exclusive flock held for as long as it lives, if it could be taken (held()); released by
// the kernel if the process dies.
class FileLock {
 public:
  explicit FileLock(const fs::path& file) : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0) {
      error_ = "cannot open '" + file.string() + "': " + std::strerror(errno);
      return;
    }
    while (::flock(fd_, LOCK_EX) != 0) {
      if (errno == EINTR) continue;
      error_ = "cannot lock '" + file.string() + "': " + std::strerror(errno);
      ::close(fd_);
      fd_ = -1;
      return;
    }
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  bool held() const { return fd_ >= 0; }
  const std::string& error() const { return error_; }  // why it is not held

 private:
  int fd_;
  std::string error_;
};

}  // namespace

std::string canonical_request_text(const MeshRequest& r) {
  std::ostringstream key;
  key << "domain";
  for (Point p : r.domain) key << ' ' << point_text(p);
  key << "\nboundaries " << r.boundaries.size() << '\n';
  for (const NamedSegment& b : r.boundaries) key << b.name.size() << ':' << b.name << ' ' << point_text(b.from) << ' ' << point_text(b.to) << '\n';
  key << "refinement_lines " << r.refinement_lines.size() << '\n';
  for (const Segment& s : r.refinement_lines) key << point_text(s.from) << ' ' << point_text(s.to) << '\n';
  if (!r.refinement_points.empty()) {
    key << "refinement_points " << r.refinement_points.size() << '\n';
    for (const RefinePoint& p : r.refinement_points)
      key << point_text(p.point) << ' ' << exact(p.size) << ' ' << exact(p.radius) << '\n';
  }
  key << "regions " << r.regions.size() << '\n';
  for (const NamedPolygon& g : r.regions) {
    key << g.name.size() << ':' << g.name;
    for (Point p : g.polygon) key << ' ' << point_text(p);
    key << '\n';
  }
  key << "size " << exact(r.size) << "\nfracture_size " << exact(r.fracture_size) << "\nrefine_distance "
      << exact(r.refine_distance) << "\nalgorithm " << r.algorithm << "\nthreads " << r.threads
      << "\ntile_triangles " << r.tile_triangles << "\ntiles meshed apart\nsmoothing " << r.smoothing
      << '\n';
  return key.str();
}

std::optional<TriangleMesh> load_cached_mesh(const fs::path& file, const std::string& key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  Reader read(in, file);
  std::string magic(sizeof kMagic - 1, '\0');
  read.bytes(magic.data(), magic.size());
  if (magic != kMagic) read.fail("is not a cached mesh of this format");
  if (read.text() != key) return std::nullopt;
  TriangleMesh mesh;
  mesh.nodes = read.array<Point>();
  mesh.triangles = read.array<std::array<int, 3>>();
  mesh.region = read.array<int>();
  for (std::size_t n = read.count(); n > 0; --n) mesh.region_names.push_back(read.text());
  mesh.boundary_edges = read.array<BoundaryEdge>();
  for (std::size_t n = read.count(); n > 0; --n) mesh.boundary_names.push_back(read.text());
  read.check_sum();
  try {
    validate(mesh);
  } catch (const std::runtime_error& e) {
    read.fail(std::string("is not a valid mesh: ") + e.what());
  }
  return mesh;
}

void save_cached_mesh(const fs::path& file, const TriangleMesh& mesh, const std::string& key) {
  const fs::path partial = fs::path(file).concat(".partial");
  try {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write '" + partial.string() + "'");
    Writer write(out);
    write.bytes(kMagic, sizeof kMagic - 1);
    write.text(key);
    write.array(mesh.nodes);
    write.array(mesh.triangles);
    write.array(mesh.region);
    write.count(mesh.region_names.size());
    for (const std::string& name : mesh.region_names) write.text(name);
    write.array(mesh.boundary_edges);
    write.count(mesh.boundary_names.size());
    for (const std::string& name : mesh.boundary_names) write.text(name);
    write.checksum();
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + partial.string() + "'");
    fs::rename(partial, file);
  } catch (...) {
    std::error_code ignored;
    if (!fs::is_directory(partial, ignored)) fs::remove(partial, ignored);
    throw;
  }
}

namespace {

// The entry at `file` made from `key`; nothing when there is none or it holds another key. An
// entry that cannot be used is removed, so that the mesh made instead takes its place, and
// `warnings` say so.
std::optional<TriangleMesh> read_entry(const fs::path& file, const std::string& key, std::vector<std::string>& warnings) {
  try {
    return load_cached_mesh(file, key);
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(file, ignored);
    warnings.push_back(std::string(e.what()) + "; it is discarded and the mesh made again");
    return std::nullopt;
  }
}

std::string hex_name(std::uint64_t hash) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(hash));
  return name;
}

// A name the cache gives its files: 16 lowercase hex digits, then .mesh, .lock or .mesh.partial.
bool is_cache_file(std::string_view name) {
  constexpr std::size_t kDigits = 16;
  if (name.size() <= kDigits) return false;
  for (char c : name.substr(0, kDigits))
    if (!std::isdigit(static_cast<unsigned char>(c)) && (c < 'a' || c > 'f')) return false;
  const std::string_view rest = name.substr(kDigits);
  return rest == ".mesh" || rest == ".lock" || rest == ".mesh.partial";
}

}  // namespace

CachedMesh generate_or_reuse_mesh(const MeshRequest& request, const fs::path& folder) {
  const std::string key = canonical_request_text(request);
  const std::string name = hex_name(fnv1a(key));
  CachedMesh cached;
  cached.file = folder / (name + ".mesh");
  // A cache that cannot be used (a read-only or full disk, a file where the folder should be)
  // costs the run its meshing time, not the run.
  std::error_code ignored;
  fs::create_directories(folder, ignored);  // if it cannot be made, the lock says why
  const FileLock lock(folder / (name + ".lock"));
  if (!lock.held()) {
    cached.warnings.push_back("the mesh cache '" + folder.string() + "' cannot be used (" + lock.error() +
                              "); meshing without it");
    cached.mesh = generate_mesh(request);
    return cached;
  }
  if (std::optional<TriangleMesh> mesh = read_entry(cached.file, key, cached.warnings)) {
    cached.mesh = std::move(*mesh);
    cached.reused = true;
    return cached;
  }
  cached.mesh = generate_mesh(request);
  try {
    save_cached_mesh(cached.file, cached.mesh, key);
    cached.stored = true;
  } catch (const std::exception& e) {
    cached.warnings.push_back(std::string("the mesh was not stored in the mesh cache: ") + e.what());
  }
  return cached;
}

void remove_cache_entries(const fs::path& folder) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(folder, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status))
    throw std::runtime_error("'" + folder.string() + "' is not a folder of meshes" +
                             (fs::is_symlink(status) ? " but a symbolic link, which is not followed" : ""));
  std::vector<fs::path> entries;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (is_cache_file(entry.path().filename().string()) && !entry.is_symlink() && !entry.is_directory())
      entries.push_back(entry.path());
  for (const fs::path& entry : entries) fs::remove(entry);
}

}  // namespace hydrodda::mesh
