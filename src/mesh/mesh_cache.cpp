#include "mesh/mesh_cache.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hydrodda::mesh {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[] = "hydrodda cached mesh 1\n";

std::string exact(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%a", value);
  return text;
}

std::string point_text(Point p) { return exact(p.x) + " " + exact(p.y); }

// FNV-1a, 64 bits: a file name for a key, not a guard (the key itself is compared on load).
// Written here as a hash of a few kilobytes needs no library.
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

class Writer {
 public:
  explicit Writer(std::ofstream& out) : out_(out) {}
  void bytes(const void* data, std::size_t n) { out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(n)); }
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

 private:
  std::ofstream& out_;
};

class Reader {
 public:
  Reader(std::ifstream& in, const fs::path& file) : in_(in), file_(file), left_(fs::file_size(file)) {}
  void bytes(void* data, std::size_t n) {
    if (n > left_ || !in_.read(static_cast<char*>(data), static_cast<std::streamsize>(n)))
      throw std::runtime_error("cached mesh '" + file_.string() + "' is cut short");
    left_ -= n;
  }
  std::size_t count(std::size_t item_size = 1) {
    std::uint64_t v = 0;
    bytes(&v, sizeof v);
    if (v > left_ / item_size) throw std::runtime_error("cached mesh '" + file_.string() + "' is cut short");
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

 private:
  std::ifstream& in_;
  fs::path file_;
  std::uintmax_t left_;
};

// An exclusive flock held for as long as it lives; released by the kernel if the process dies.
class FileLock {
 public:
  explicit FileLock(const fs::path& file) : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw std::runtime_error("cannot open '" + file.string() + "': " + std::strerror(errno));
    while (::flock(fd_, LOCK_EX) != 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd_);
      throw std::runtime_error("cannot lock '" + file.string() + "': " + std::strerror(error));
    }
  }
  ~FileLock() { ::close(fd_); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
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
      << "\ntile_triangles " << r.tile_triangles << "\nprocesses " << r.processes << "\nsmoothing " << r.smoothing
      << '\n';
  return key.str();
}

std::optional<TriangleMesh> load_cached_mesh(const fs::path& file, const std::string& key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  Reader read(in, file);
  std::string magic(sizeof kMagic - 1, '\0');
  read.bytes(magic.data(), magic.size());
  if (magic != kMagic) throw std::runtime_error("'" + file.string() + "' is not a cached mesh");
  if (read.text() != key) return std::nullopt;
  TriangleMesh mesh;
  mesh.nodes = read.array<Point>();
  mesh.triangles = read.array<std::array<int, 3>>();
  mesh.region = read.array<int>();
  for (std::size_t n = read.count(); n > 0; --n) mesh.region_names.push_back(read.text());
  mesh.boundary_edges = read.array<BoundaryEdge>();
  for (std::size_t n = read.count(); n > 0; --n) mesh.boundary_names.push_back(read.text());
  validate(mesh);
  return mesh;
}

void save_cached_mesh(const fs::path& file, const TriangleMesh& mesh, const std::string& key) {
  const fs::path partial = fs::path(file).concat(".partial");
  {
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
    out.flush();
    if (!out) throw std::runtime_error("cannot write '" + partial.string() + "'");
  }
  fs::rename(partial, file);
}

CachedMesh generate_or_reuse_mesh(const MeshRequest& request, const fs::path& folder) {
  fs::create_directories(folder);
  const std::string key = canonical_request_text(request);
  char name[32];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(fnv1a(key)));
  CachedMesh cached;
  cached.file = folder / (std::string(name) + ".mesh");
  const FileLock lock(folder / (std::string(name) + ".lock"));
  if (std::optional<TriangleMesh> mesh = load_cached_mesh(cached.file, key)) {
    cached.mesh = std::move(*mesh);
    cached.reused = true;
    return cached;
  }
  cached.mesh = generate_mesh(request);
  save_cached_mesh(cached.file, cached.mesh, key);
  return cached;
}

}  // namespace hydrodda::mesh
