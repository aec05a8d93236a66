// The one file of the project that includes Gmsh: generating a mesh from a MeshRequest and
// reading a user's .msh file, both into a TriangleMesh. Built as a plugin of its own
// (hydrodda_gmsh_mesher.so), which gmsh_loader.cpp loads the first time a run needs a mesh:
// Gmsh and the OpenCASCADE libraries it links take 146,000 relocations to load, 0.1–0.3 s at
// every start of the program, which a run without a fluid mesh does not need.
#include <gmsh.h>
#include <omp.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <cstdint>
#include <deque>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "mesh/gmsh/gmsh_plugin.hpp"
#include "mesh/line_distance.hpp"
#include "mesh/mesh_estimate.hpp"
#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {
namespace {

// Gmsh is a process-wide singleton: one session at a time, initialised on entry and
// finalised on exit (also when an exception leaves), with its terminal output off unless
// asked. This file is the only user of Gmsh in the program, so no one else holds it.
// Gmsh sets the process's OpenMP thread count to its General.NumThreads (omp_set_num_threads):
// the count the program had is given back at the end, or everything after the mesh (the DDA,
// the porosity clip, the face loads) would run on one thread.
class GmshSession {
 public:
  explicit GmshSession(bool verbose) : lock_(mutex()), openmp_threads_(omp_get_max_threads()) {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::option::setNumber("General.Verbosity", verbose ? 5 : 1);
    gmsh::logger::start();
    gmsh::model::add("hydrodda");
  }
  ~GmshSession() {
    try {
      gmsh::logger::stop();
      gmsh::model::mesh::removeSizeCallback();
      gmsh::model::remove();
      gmsh::finalize();
    } catch (...) {  // a destructor must not throw; Gmsh's state is discarded either way
    }
    omp_set_num_threads(openmp_threads_);
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  int openmp_threads_;
};

// Gmsh reports errors by throwing (a std::string in 4.8, or something else in other
// versions) and by its logger; turn either into one message.
std::string describe_gmsh_error() {
  std::string last;
  try {
    gmsh::logger::getLastError(last);
  } catch (...) {
  }
  return last.empty() ? std::string("unknown Gmsh error") : last;
}

template <class F>
void call_gmsh(const std::string& what, F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    throw std::runtime_error(what + ": " + e.what());
  } catch (const std::string& e) {
    throw std::runtime_error(what + ": " + e);
  } catch (...) {
    throw std::runtime_error(what + ": " + describe_gmsh_error());
  }
}

constexpr int kLinearTriangle = 2;  // Gmsh element type numbers
constexpr int kLinearLine = 1;

// Node tags of Gmsh → dense indices, keeping only the nodes that triangles use, in ascending
// tag order (deterministic).
struct NodeTable {
  std::vector<Point> nodes;
  std::vector<int> index_of_tag;  // -1 for unused tags
};

NodeTable collect_used_nodes(const std::vector<std::size_t>& used_tags) {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::size_t max_tag = 0;
  for (std::size_t tag : node_tags) max_tag = std::max(max_tag, tag);
  std::vector<std::size_t> position(max_tag + 1, SIZE_MAX);
  for (std::size_t i = 0; i < node_tags.size(); ++i) position[node_tags[i]] = i;

  NodeTable table;
  table.index_of_tag.assign(max_tag + 1, -1);
  std::vector<char> used(max_tag + 1, 0);
  for (std::size_t tag : used_tags) {
    if (tag > max_tag || position[tag] == SIZE_MAX)
      throw std::runtime_error("an element refers to node " + std::to_string(tag) +
                               ", which does not exist");
    used[tag] = 1;
  }
  for (std::size_t tag = 0; tag <= max_tag; ++tag) {
    if (!used[tag]) continue;
    table.index_of_tag[tag] = static_cast<int>(table.nodes.size());
    table.nodes.push_back({coords[3 * position[tag]], coords[3 * position[tag] + 1]});
  }
  return table;
}

// Triangles of the surface entity `tag`, as Gmsh node tags; throws on any other 2D element.
std::vector<std::size_t> get_surface_triangles(int tag) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, tag);
  std::vector<std::size_t> triangles;
  for (std::size_t k = 0; k < types.size(); ++k) {
    if (types[k] != kLinearTriangle) {
      std::string name;
      int dim = 0, order = 0, nodes = 0, primary = 0;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(types[k], name, dim, order, nodes, local, primary);
      throw std::runtime_error("surface " + std::to_string(tag) + " has elements of type '" +
                               name + "'; only 3-node triangles are supported");
    }
    triangles.insert(triangles.end(), node_tags[k].begin(), node_tags[k].end());
  }
  return triangles;
}

// Room for every triangle of some surfaces at once (Gmsh node tags, three per triangle): grown
// a surface at a time, the lists would end with up to twice the memory they need.
void reserve_triangles(TriangleMesh& mesh, const std::vector<std::vector<std::size_t>>& surfaces) {
  std::size_t count = mesh.triangles.size();
  for (const std::vector<std::size_t>& tags : surfaces) count += tags.size() / 3;
  mesh.triangles.reserve(count);
  mesh.region.reserve(count);
}

// Appends the triangles (Gmsh node tags, three per triangle) with a region tag, turned
// counter-clockwise.
void append_triangles(TriangleMesh& mesh, const NodeTable& table,
                      const std::vector<std::size_t>& tags, int region) {
  for (std::size_t i = 0; i + 2 < tags.size(); i += 3) {
    std::array<int, 3> tri{table.index_of_tag[tags[i]], table.index_of_tag[tags[i + 1]],
                           table.index_of_tag[tags[i + 2]]};
    if (geometry::orient(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]) < 0)
      std::swap(tri[1], tri[2]);
    mesh.triangles.push_back(tri);
    mesh.region.push_back(region);
  }
}

// The triangles of some surfaces (Gmsh node tags, three a triangle, per surface) and the
// coordinates of every node they use, in ascending tag order.
struct SurfaceMeshes {
  std::vector<std::vector<std::size_t>> triangles;
  std::vector<std::pair<std::size_t, Point>> nodes;
};

SurfaceMeshes take_surface_meshes(const std::vector<int>& surface_tags) {
  SurfaceMeshes out;
  std::vector<std::size_t> all_tags;
  for (int tag : surface_tags) {
    out.triangles.push_back(get_surface_triangles(tag));
    all_tags.insert(all_tags.end(), out.triangles.back().begin(), out.triangles.back().end());
  }
  const NodeTable table = collect_used_nodes(all_tags);
  for (std::size_t tag = 0; tag < table.index_of_tag.size(); ++tag)
    if (const int i = table.index_of_tag[tag]; i >= 0) out.nodes.push_back({tag, table.nodes[i]});
  return out;
}

// The table of nodes listed in ascending tag order.
NodeTable node_table(const std::vector<std::pair<std::size_t, Point>>& nodes) {
  NodeTable table;
  table.index_of_tag.assign(nodes.empty() ? 0 : nodes.back().first + 1, -1);
  for (const auto& [tag, p] : nodes) {
    table.index_of_tag[tag] = static_cast<int>(table.nodes.size());
    table.nodes.push_back(p);
  }
  return table;
}

// SurfaceMeshes through a pipe: counts as 64-bit words, coordinates as doubles.
void append_words(std::string& bytes, const void* data, std::size_t size) {
  bytes.append(static_cast<const char*>(data), size);
}

std::string encode_surface_meshes(const SurfaceMeshes& m) {
  std::string bytes;
  const auto put = [&](std::uint64_t v) { append_words(bytes, &v, sizeof v); };
  put(m.triangles.size());
  for (const auto& t : m.triangles) {
    put(t.size());
    for (std::size_t tag : t) put(tag);
  }
  put(m.nodes.size());
  for (const auto& [tag, p] : m.nodes) {
    put(tag);
    append_words(bytes, &p.x, sizeof p.x);
    append_words(bytes, &p.y, sizeof p.y);
  }
  return bytes;
}

SurfaceMeshes decode_surface_meshes(const std::string& bytes) {
  std::size_t at = 0;
  const auto take = [&](void* out, std::size_t size) {
    if (size > bytes.size() - at) throw std::runtime_error("the meshing process sent a message cut short");
    std::memcpy(out, bytes.data() + at, size);
    at += size;
  };
  const auto get = [&] {
    std::uint64_t v = 0;
    take(&v, sizeof v);
    return v;
  };
  SurfaceMeshes m;
  m.triangles.resize(get());
  for (auto& t : m.triangles) {
    t.resize(get());
    for (std::size_t& tag : t) tag = get();
  }
  m.nodes.resize(get());
  for (auto& [tag, p] : m.nodes) {
    tag = get();
    take(&p.x, sizeof p.x);
    take(&p.y, sizeof p.y);
  }
  if (at != bytes.size()) throw std::runtime_error("the meshing process sent more than a mesh");
  return m;
}

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

std::string read_all(int fd) {
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  return bytes;
}

// Meshes only `tags` of the model's surfaces (their curves already meshed).
void mesh_surfaces_only(const std::vector<int>& tags, const std::vector<int>& others) {
  gmsh::vectorpair hidden;
  for (int tag : others) hidden.push_back({2, tag});
  gmsh::vectorpair shown;
  for (int tag : tags) shown.push_back({2, tag});
  gmsh::model::setVisibility(hidden, 0, false);
  gmsh::model::setVisibility(shown, 1, false);
  gmsh::option::setNumber("Mesh.MeshOnlyVisible", 1);
  gmsh::model::mesh::generate(2);
}

// A child process meshing one surface, and the pipe it sends its mesh back through.
struct MeshingChild {
  pid_t pid = -1;
  int channel = -1;
};

// Forks a child that meshes the surfaces `mine` in turn (the others of `tags` hidden) from this
// process's state, sends "M" and their triangles and new nodes (or "E" and what went wrong), and
// exits. It dies with this process (PR_SET_PDEATHSIG), so an interrupt while meshing ends all.
MeshingChild start_meshing_child(const std::vector<int>& mine, const std::vector<int>& tags) {
  int channel[2];
  if (::pipe(channel) != 0) throw std::runtime_error(std::string("no pipe for a meshing process: ") + std::strerror(errno));
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(channel[0]);
    ::close(channel[1]);
    throw std::runtime_error(std::string("no process to mesh with: ") + std::strerror(errno));
  }
  if (child == 0) {
    ::close(channel[0]);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);
    std::string message;
    int status = 0;
    try {
      std::vector<int> others;
      for (int t : tags)
        if (std::find(mine.begin(), mine.end(), t) == mine.end()) others.push_back(t);
      mesh_surfaces_only(mine, others);
      message = "M" + encode_surface_meshes(take_surface_meshes(mine));
    } catch (const std::exception& e) {
      message = std::string("E") + e.what();
      status = 1;
    } catch (const std::string& e) {
      message = "E" + e;
      status = 1;
    } catch (...) {
      message = "E" + describe_gmsh_error();
      status = 1;
    }
    write_all(channel[1], message);
    ::_exit(status);  // Gmsh's state is the parent's to finalise
  }
  ::close(channel[1]);
  return {child, channel[0]};
}

// The mesh `child` sends; throws std::runtime_error if it failed.
SurfaceMeshes finish_meshing_child(MeshingChild& child) {
  const std::string message = read_all(child.channel);
  ::close(child.channel);
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  child.pid = -1;
  if (message.empty() || message[0] != 'M' || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("a meshing process failed" +
                             (message.size() > 1 && message[0] == 'E' ? ": " + message.substr(1) : std::string()));
  return decode_surface_meshes(message.substr(1));
}

void stop_meshing_child(MeshingChild& child) {
  if (child.pid < 0) return;
  ::kill(child.pid, SIGKILL);
  ::close(child.channel);
  ::waitpid(child.pid, nullptr, 0);
  child.pid = -1;
}

// Groups of surfaces a tiled mesh is meshed in, each by a child process of its own: surface i
// in group i % groups, groups = min(surfaces, kMeshingGroups). Fixed by the surfaces alone, so
// that the mesh does not depend on the processes; as many as a large machine's cores, few enough
// that the forks cost little (a fork per tile of the 1.26-million-triangle mesh, 250 of them,
// took 18 s of CPU against 12 s for two processes).
constexpr std::size_t kMeshingGroups = 32;

// The surfaces' meshes, each group of them (kMeshingGroups) made by a child process of its own,
// up to `processes` at once: their curves are meshed first, here, so that every surface sees
// the same nodes along the edges it shares; then each child, forked from that state, meshes its
// group's surfaces in turn on one thread. What Gmsh makes of a surface depends on the surfaces
// meshed before it in the same process, and the groups are the same whatever the number of
// processes: the mesh is the same from run to run, machine to machine and core count to core
// count. (Gmsh's own threads mesh surfaces at once but not reproducibly: 545,305 or 545,307
// nodes for the 1.09-million-triangle seal from one run to the next.) Nodes are numbered the
// curves' first, then each surface's new nodes in the surfaces' order, each surface's in the
// order made.
SurfaceMeshes mesh_surfaces_in_processes(const std::vector<int>& tags, int processes) {
  gmsh::model::mesh::generate(1);
  std::size_t curve_nodes = 0;  // the largest tag of the curves' nodes
  {
    std::vector<std::size_t> node_tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
    for (std::size_t tag : node_tags) curve_nodes = std::max(curve_nodes, tag);
  }
  const std::size_t groups = std::min(tags.size(), kMeshingGroups);
  std::vector<std::vector<int>> group_tags(groups);
  for (std::size_t i = 0; i < tags.size(); ++i) group_tags[i % groups].push_back(tags[i]);
  // The children's meshes read in the groups' order; the next child starts as one ends.
  std::vector<SurfaceMeshes> meshed(groups);
  std::deque<std::pair<std::size_t, MeshingChild>> running;
  try {
    std::size_t next = 0;
    while (next < groups || !running.empty()) {
      for (; next < groups && running.size() < static_cast<std::size_t>(processes); ++next)
        running.emplace_back(next, start_meshing_child(group_tags[next], tags));
      meshed[running.front().first] = finish_meshing_child(running.front().second);
      running.pop_front();
    }
  } catch (...) {
    for (auto& [group, child] : running) stop_meshing_child(child);
    throw;
  }

  // Renumber the surfaces' new nodes as one process meshing the surfaces in order would.
  std::vector<NodeTable> group_nodes;
  for (const SurfaceMeshes& m : meshed) group_nodes.push_back(node_table(m.nodes));
  SurfaceMeshes all;
  std::size_t next = curve_nodes + 1;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const NodeTable& from_nodes = group_nodes[i % groups];
    const std::vector<std::size_t>& triangles = meshed[i % groups].triangles.at(i / groups);
    std::map<std::size_t, std::size_t> renumber;  // this surface's new nodes
    for (std::size_t tag : triangles)
      if (tag > curve_nodes) renumber.emplace(tag, 0);
    for (auto& [old_tag, new_tag] : renumber) new_tag = next++;  // ascending old tags: the order made
    std::vector<std::size_t>& renumbered = all.triangles.emplace_back();
    for (std::size_t tag : triangles) {
      const std::size_t final_tag = tag > curve_nodes ? renumber.at(tag) : tag;
      renumbered.push_back(final_tag);
      all.nodes.push_back({final_tag, from_nodes.nodes[from_nodes.index_of_tag[tag]]});
    }
  }
  std::sort(all.nodes.begin(), all.nodes.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
  all.nodes.erase(std::unique(all.nodes.begin(), all.nodes.end(),
                              [](const auto& u, const auto& v) { return u.first == v.first; }),
                  all.nodes.end());
  return all;
}

// The domain with each named-segment end point that lies on a domain edge inserted as a
// vertex, so that mesh edges end exactly where named boundaries end.
geometry::Polygon insert_segment_ends(const geometry::Polygon& domain,
                                      const std::vector<NamedSegment>& segments, double tolerance) {
  geometry::Polygon out;
  const std::size_t n = domain.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = domain[i], b = domain[(i + 1) % n];
    out.push_back(a);
    std::vector<std::pair<double, Point>> inserted;
    for (const NamedSegment& s : segments)
      for (Point p : {s.from, s.to}) {
        if (geometry::distance_to_segment(p, a, b) > tolerance) continue;
        if (geometry::distance(p, a) <= tolerance || geometry::distance(p, b) <= tolerance) continue;
        inserted.push_back({geometry::dot(p - a, b - a) / geometry::dot(b - a, b - a), p});
      }
    std::sort(inserted.begin(), inserted.end(),
              [](const auto& u, const auto& v) { return u.first < v.first; });
    for (const auto& [t, p] : inserted)
      if (geometry::distance(out.back(), p) > tolerance) out.push_back(p);
  }
  return out;
}

int add_occ_polygon(const geometry::Polygon& polygon) {
  std::vector<int> points, lines;
  for (Point p : polygon) points.push_back(gmsh::model::occ::addPoint(p.x, p.y, 0.0));
  for (std::size_t i = 0; i < points.size(); ++i)
    lines.push_back(gmsh::model::occ::addLine(points[i], points[(i + 1) % points.size()]));
  const int loop = gmsh::model::occ::addCurveLoop(lines);
  return gmsh::model::occ::addPlaneSurface({loop});
}

// Gmsh's Delaunay costs more per triangle the more triangles one surface holds: its per-surface
// vertex sets and maps (the std::set<MVertex*> of _deleteUnusedVertices, the vertex-to-triangle
// map of laplaceSmoothing, the radius-ordered triangle set of bowyerWatson) outgrow the caches.
// Measured on the 100 m x 20 m seal at 0.07 m (1.08 million triangles, one thread, CPU time on
// a loaded host): 49 s as one surface, 28 s over 10 x 4 tiles, 19 s over 20 x 8, 13 s over
// 33 x 7 (about 5,000 triangles each). So a large mesh is made over a grid of rectangular
// tiles cut into the domain (MeshRequest::tile_triangles); the tile edges become ordinary mesh
// edges. A mesh of fewer than ten tiles' worth (50,000 triangles by default; every shipped
// scenario) stays one surface, as before: there one surface costs little more.
constexpr double kLeastTiles = 10.0;

struct TileGrid {
  int columns = 1, rows = 1;
  int count() const { return columns * rows; }
};

TileGrid choose_tiles(const MeshRequest& request, const geometry::Box& box) {
  TileGrid grid;
  if (request.tile_triangles <= 0) return grid;
  const double tiles = estimate_triangle_count(request).total() / request.tile_triangles;
  if (!(tiles >= kLeastTiles)) return grid;
  // Tiles as near square as the box allows: columns / rows ≈ width / height.
  const double aspect = box.width() / box.height();
  grid.columns = std::max(1, static_cast<int>(std::lround(std::sqrt(tiles * aspect))));
  grid.rows = std::max(1, static_cast<int>(std::lround(tiles / grid.columns)));
  return grid;
}

// The tiles as OpenCASCADE rectangles covering the box.
std::vector<int> add_occ_tiles(const TileGrid& grid, const geometry::Box& box) {
  std::vector<int> tiles;
  const double dx = box.width() / grid.columns, dy = box.height() / grid.rows;
  for (int j = 0; j < grid.rows; ++j)
    for (int i = 0; i < grid.columns; ++i)
      tiles.push_back(gmsh::model::occ::addRectangle(box.lo.x + i * dx, box.lo.y + j * dy, 0.0, dx, dy));
  return tiles;
}

void check_polygon(const geometry::Polygon& polygon, const std::string& what) {
  if (polygon.size() < 3) throw std::runtime_error(what + " has fewer than 3 vertices");
  if (!(geometry::area(polygon) > 0.0)) throw std::runtime_error(what + " has zero area");
  if (const auto hit = geometry::find_self_intersection(polygon))
    throw std::runtime_error(what + " intersects itself (edges " + std::to_string(hit->first) +
                             " and " + std::to_string(hit->second) + ")");
}

void check_request(const MeshRequest& request) {
  check_polygon(request.domain, "mesh domain");
  for (const NamedPolygon& r : request.regions) check_polygon(r.polygon, "region '" + r.name + "'");
  if (!(request.size > 0.0)) throw std::runtime_error("mesh size must be positive");
  if (request.threads < 1) throw std::runtime_error("mesh threads must be at least 1");
  if (request.processes < 1) throw std::runtime_error("mesh processes must be at least 1");
  if (request.tile_triangles < 0) throw std::runtime_error("mesh tile_triangles must not be negative");
  if (request.smoothing < -1) throw std::runtime_error("mesh smoothing must be -1 (chosen) or a number of passes >= 0");
  if (request.algorithm != 1 && request.algorithm != 5 && request.algorithm != 6)
    throw std::runtime_error("mesh algorithm must be 1 (MeshAdapt), 5 (Delaunay) or 6 (Frontal-Delaunay)");
  if (!request.refinement_lines.empty()) {
    if (!(request.fracture_size > 0.0)) throw std::runtime_error("mesh fracture_size must be positive");
    if (!(request.refine_distance > 0.0))
      throw std::runtime_error("mesh refine_distance must be positive");
  }
}

}  // namespace

TriangleMesh generate_mesh_with_gmsh(const MeshRequest& request) {
  check_request(request);
  const geometry::Box box = geometry::bounding_box(request.domain);
  const double tolerance = 1e-9 * std::max(box.width(), box.height());
  geometry::Polygon domain = insert_segment_ends(request.domain, request.boundaries, tolerance);
  if (geometry::signed_area(domain) < 0) std::reverse(domain.begin(), domain.end());

  TriangleMesh mesh;
  mesh.region_names.push_back("domain");
  std::vector<int> region_of_input;  // region tag of each region polygon
  for (const NamedPolygon& r : request.regions) {
    int tag = find_region(mesh, r.name);
    if (tag < 0) {
      tag = static_cast<int>(mesh.region_names.size());
      mesh.region_names.push_back(r.name);
    }
    region_of_input.push_back(tag);
  }

  GmshSession session(request.verbose);
  bool tiled = false;
  // Surfaces of the meshed domain and the region tag of each.
  std::vector<std::pair<int, int>> surfaces;
  call_gmsh("Gmsh could not build the geometry", [&] {
    const int domain_surface = add_occ_polygon(domain);
    const TileGrid tiles = choose_tiles(request, box);
    tiled = tiles.count() > 1;
    if (request.regions.empty() && tiles.count() == 1) {
      surfaces.push_back({domain_surface, 0});
    } else {
      gmsh::vectorpair tools, out;
      for (const NamedPolygon& r : request.regions) tools.push_back({2, add_occ_polygon(r.polygon)});
      if (tiles.count() > 1)
        for (int tile : add_occ_tiles(tiles, box)) tools.push_back({2, tile});
      std::vector<gmsh::vectorpair> map;
      // Fragment makes the region boundaries and the tile edges edges of the domain's pieces.
      gmsh::model::occ::fragment({{2, domain_surface}}, tools, out, map);
      std::map<int, int> region_of_surface;  // pieces of the domain only
      for (const auto& [dim, tag] : map[0]) region_of_surface[tag] = 0;
      for (std::size_t i = 0; i < request.regions.size(); ++i)
        for (const auto& [dim, tag] : map[i + 1])  // later regions take precedence
          if (region_of_surface.count(tag)) region_of_surface[tag] = region_of_input[i];
      gmsh::vectorpair outside;
      for (const auto& [dim, tag] : out)
        if (dim == 2 && !region_of_surface.count(tag)) outside.push_back({2, tag});
      if (!outside.empty()) gmsh::model::occ::remove(outside, true);
      for (const auto& [tag, region] : region_of_surface) surfaces.push_back({tag, region});
    }
    gmsh::model::occ::synchronize();
  });

  // A tiled mesh is made by child processes, MeshRequest::processes at once.
  const bool in_processes = tiled && surfaces.size() >= 2;
  call_gmsh("Gmsh could not mesh the domain", [&] {
    gmsh::option::setNumber("Mesh.Algorithm", request.algorithm);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", request.size);
    gmsh::option::setNumber("Mesh.Smoothing", request.smoothing >= 0 ? request.smoothing : tiled ? 0 : 1);
    gmsh::option::setNumber("General.NumThreads", request.threads);
    if (!request.refinement_lines.empty() || !request.refinement_points.empty()) {
      // Gmsh's Distance + Threshold fields, evaluated with the exact distance to the lines
      // (a Distance field would sample them; its sample nodes would also join the mesh),
      // through an index of the lines: only those within refine_distance set the size. The
      // refinement points are few and are measured directly.
      const auto lines = std::make_shared<const LineDistance>(request.refinement_lines, request.refine_distance);
      gmsh::model::mesh::setSizeCallback(
          [lines, request](int, int, double x, double y, double) {
            return refined_size(request, lines->nearest({x, y}), {x, y});
          });
    }
    if (!in_processes) gmsh::model::mesh::generate(2);
  });

  call_gmsh("Gmsh produced an unusable mesh", [&] {
    std::vector<int> tags;
    for (const auto& [tag, region] : surfaces) tags.push_back(tag);
    const SurfaceMeshes meshes =
        in_processes ? mesh_surfaces_in_processes(tags, request.processes) : take_surface_meshes(tags);
    const NodeTable table = node_table(meshes.nodes);
    mesh.nodes = table.nodes;
    reserve_triangles(mesh, meshes.triangles);
    for (std::size_t s = 0; s < surfaces.size(); ++s)
      append_triangles(mesh, table, meshes.triangles[s], surfaces[s].second);
  });
  if (mesh.triangles.empty()) throw std::runtime_error("Gmsh produced no triangles");
  name_boundary_edges(mesh, request.boundaries, box);
  validate(mesh);
  return mesh;
}

TriangleMesh read_msh_with_gmsh(const std::string& path, bool verbose) {
  if (!std::ifstream(path)) throw std::runtime_error("cannot open mesh file '" + path + "'");
  const std::string where = "mesh file '" + path + "'";
  GmshSession session(verbose);
  TriangleMesh mesh;
  call_gmsh(where, [&] {
    gmsh::open(path);
    std::string error;
    gmsh::logger::getLastError(error);
    if (!error.empty()) throw std::runtime_error(error);

    mesh.region_names.push_back("domain");
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, 2);
    std::vector<std::pair<std::vector<std::size_t>, int>> blocks;  // triangles, region
    std::vector<std::size_t> all_tags;
    for (const auto& [dim, tag] : entities) {
      std::vector<int> groups;
      gmsh::model::getPhysicalGroupsForEntity(2, tag, groups);
      int region = 0;
      if (!groups.empty()) {
        std::string name;
        gmsh::model::getPhysicalName(2, groups.front(), name);
        if (name.empty()) name = std::to_string(groups.front());
        region = find_region(mesh, name);
        if (region < 0) {
          region = static_cast<int>(mesh.region_names.size());
          mesh.region_names.push_back(name);
        }
      }
      blocks.push_back({get_surface_triangles(tag), region});
      all_tags.insert(all_tags.end(), blocks.back().first.begin(), blocks.back().first.end());
    }
    if (all_tags.empty()) throw std::runtime_error("no triangles");
    const NodeTable table = collect_used_nodes(all_tags);
    mesh.nodes = table.nodes;
    mesh.triangles.reserve(all_tags.size() / 3);
    mesh.region.reserve(all_tags.size() / 3);
    for (const auto& [tags, region] : blocks) append_triangles(mesh, table, tags, region);

    // 1D physical groups name the boundary edges (the first group, by tag, wins).
    std::map<std::pair<int, int>, int> group_of_edge;
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, 1);
    for (const auto& [dim, group] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(1, group, name);
      if (name.empty()) name = std::to_string(group);
      int index = find_boundary(mesh, name);
      if (index < 0) {
        index = static_cast<int>(mesh.boundary_names.size());
        mesh.boundary_names.push_back(name);
      }
      std::vector<int> curves;
      gmsh::model::getEntitiesForPhysicalGroup(1, group, curves);
      for (int curve : curves) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> element_tags, node_tags;
        gmsh::model::mesh::getElements(types, element_tags, node_tags, 1, curve);
        for (std::size_t k = 0; k < types.size(); ++k) {
          if (types[k] != kLinearLine)
            throw std::runtime_error("physical curve '" + name + "' has elements that are not 2-node lines");
          for (std::size_t i = 0; i + 1 < node_tags[k].size(); i += 2) {
            const std::size_t a = node_tags[k][i], b = node_tags[k][i + 1];
            if (a >= table.index_of_tag.size() || b >= table.index_of_tag.size()) continue;
            const int u = table.index_of_tag[a], v = table.index_of_tag[b];
            if (u < 0 || v < 0) continue;
            group_of_edge.try_emplace({std::min(u, v), std::max(u, v)}, index);
          }
        }
      }
    }
    for (const auto& [a, b] : find_boundary_edges(mesh.triangles)) {
      const auto it = group_of_edge.find({std::min(a, b), std::max(a, b)});
      mesh.boundary_edges.push_back({{a, b}, it == group_of_edge.end() ? BoundaryEdge::kUnnamed : it->second});
    }
  });
  try {
    validate(mesh);
  } catch (const std::exception& e) {
    throw std::runtime_error(where + ": " + e.what());
  }
  return mesh;
}

}  // namespace hydrodda::mesh

// Exceptions cross into the program as they would from a function of its own (one libstdc++).
void hydrodda_gmsh_generate_mesh(
    const hydrodda::mesh::MeshRequest& request, hydrodda::mesh::TriangleMesh& mesh) {
  mesh = hydrodda::mesh::generate_mesh_with_gmsh(request);
}

void hydrodda_gmsh_read_msh(
    const std::string& path, bool verbose, hydrodda::mesh::TriangleMesh& mesh) {
  mesh = hydrodda::mesh::read_msh_with_gmsh(path, verbose);
}
