#include "geometry/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/portable_random.hpp"

namespace hydrodda::geometry {

namespace {

// A cell's vertex and the source of the edge that leaves it (Tessellation::edge_sources).
struct LabelledVertex {
  Point point;
  int source = -1;
};
using LabelledPolygon = std::vector<LabelledVertex>;

// Sutherland–Hodgman by one half-plane {x : dot(x − m, n) >= 0}, the edges it makes
// labelled `source`; the others keep theirs. Convex in, convex out.
LabelledPolygon clip_by_half_plane(const LabelledPolygon& in, Point m, Point n, int source) {
  LabelledPolygon out;
  const std::size_t count = in.size();
  for (std::size_t k = 0; k < count; ++k) {
    const LabelledVertex& p = in[k];
    const LabelledVertex& q = in[(k + 1) % count];
    const double dp = dot(p.point - m, n);
    const double dq = dot(q.point - m, n);
    const auto crossing = [&] { return p.point + dp / (dp - dq) * (q.point - p.point); };
    if (dp >= 0) {
      out.push_back(p);
      if (dq < 0) out.push_back({crossing(), source});  // along the bisector to where it re-enters
    } else if (dq >= 0) {
      out.push_back({crossing(), p.source});  // along p → q from the crossing
    }
  }
  return out;
}

// Seeds in buckets of side `size`, for the neighbours of each.
class SeedGrid {
 public:
  SeedGrid(std::span<const Point> seeds, double size) : seeds_(seeds), size_(size) {
    for (std::size_t i = 0; i < seeds.size(); ++i) buckets_[key(seeds[i])].push_back(static_cast<int>(i));
  }
  // The seeds within `radius` of seed i (i left out), nearest first, then by index.
  std::vector<int> near(int i, double radius) const {
    const Point s = seeds_[static_cast<std::size_t>(i)];
    const auto [cx, cy] = key(s);
    const long long reach = static_cast<long long>(std::ceil(radius / size_));
    std::vector<std::pair<double, int>> found;
    for (long long x = cx - reach; x <= cx + reach; ++x)
      for (long long y = cy - reach; y <= cy + reach; ++y) {
        const auto bucket = buckets_.find({x, y});
        if (bucket == buckets_.end()) continue;
        for (int j : bucket->second) {
          const double d = distance(s, seeds_[static_cast<std::size_t>(j)]);
          if (j != i && d <= radius) found.emplace_back(d, j);
        }
      }
    std::sort(found.begin(), found.end());
    std::vector<int> out;
    for (const auto& f : found) out.push_back(f.second);
    return out;
  }

 private:
  std::pair<long long, long long> key(Point p) const {
    return {static_cast<long long>(std::floor(p.x / size_)), static_cast<long long>(std::floor(p.y / size_))};
  }
  std::span<const Point> seeds_;
  double size_;
  std::map<std::pair<long long, long long>, std::vector<int>> buckets_;
};

LabelledPolygon make_voronoi_cell(std::span<const Point> polygon, std::span<const Point> seeds, const SeedGrid& grid,
                                  int i, double size) {
  const Point s = seeds[static_cast<std::size_t>(i)];
  double radius = 3.0 * size;
  for (;;) {
    LabelledPolygon cell;
    for (std::size_t k = 0; k < polygon.size(); ++k) cell.push_back({polygon[k], -1 - static_cast<int>(k)});
    for (int j : grid.near(i, radius)) {
      const Point t = seeds[static_cast<std::size_t>(j)];
      cell = clip_by_half_plane(cell, 0.5 * (s + t), s - t, j);
      if (cell.empty()) break;
    }
    double reach = 0.0;
    for (const LabelledVertex& v : cell) reach = std::max(reach, distance(v.point, s));
    if (2.0 * reach <= radius) return cell;
    radius = 2.0 * reach * (1.0 + 1e-9);
  }
}

// How firmly a cell's vertex is tied to the tessellated polygon: 2 at one of its corners (both
// edges at the vertex on its edges), 1 on one of its edges, 0 inside.
int count_polygon_edges_at(const LabelledPolygon& cell, std::size_t k) {
  const int before = cell[(k + cell.size() - 1) % cell.size()].source;
  return (before < 0 ? 1 : 0) + (cell[k].source < 0 ? 1 : 0);
}

// Union–find over every cell vertex: those within `tolerance` of each other share one
// position, that of the member most tied to the polygon (count_polygon_edges_at), the first
// of those (in cell and vertex order). Then each cell drops the edges that joined two
// vertices of one group, keeping the labels of the edges that remain. A polygon's corner
// welded to a bisector's crossing of an edge beside it would move off the other edge, and
// the sub-blocks would no longer fill the polygon: their faces there would stand up to
// `tolerance` off the neighbouring block's, and carry nothing of the stress across them.
void weld_vertices(std::vector<LabelledPolygon>& cells, double tolerance) {
  std::vector<Point> points;
  std::vector<int> ties;  // count_polygon_edges_at of each
  for (const LabelledPolygon& c : cells)
    for (std::size_t k = 0; k < c.size(); ++k) {
      points.push_back(c[k].point);
      ties.push_back(count_polygon_edges_at(c, k));
    }
  std::vector<int> parent(points.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    return i;
  };
  std::map<std::pair<long long, long long>, std::vector<int>> buckets;
  const auto key = [&](Point p) {
    return std::pair{static_cast<long long>(std::floor(p.x / tolerance)), static_cast<long long>(std::floor(p.y / tolerance))};
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [kx, ky] = key(points[i]);
    for (long long x = kx - 1; x <= kx + 1; ++x)
      for (long long y = ky - 1; y <= ky + 1; ++y) {
        const auto bucket = buckets.find({x, y});
        if (bucket == buckets.end()) continue;
        for (int j : bucket->second)
          if (distance(points[i], points[static_cast<std::size_t>(j)]) <= tolerance) {
            const int a = root(static_cast<int>(i));
            const int b = root(j);
            if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
          }
      }
    buckets[{kx, ky}].push_back(static_cast<int>(i));
  }
  std::vector<int> kept_point(points.size(), -1);  // by group root: the member whose position it takes
  for (std::size_t i = 0; i < points.size(); ++i) {
    int& kept = kept_point[static_cast<std::size_t>(root(static_cast<int>(i)))];
    if (kept < 0 || ties[i] > ties[static_cast<std::size_t>(kept)]) kept = static_cast<int>(i);
  }
  std::size_t next = 0;
  for (LabelledPolygon& c : cells) {
    std::vector<int> group;
    for (LabelledVertex& v : c) {
      group.push_back(root(static_cast<int>(next++)));
      v.point = points[static_cast<std::size_t>(kept_point[static_cast<std::size_t>(group.back())])];
    }
    LabelledPolygon kept;
    for (std::size_t k = 0; k < c.size(); ++k)
      if (group[k] != group[(k + 1) % c.size()]) kept.push_back(c[k]);
    c = std::move(kept);
  }
}

std::vector<Point> points_of(const LabelledPolygon& cell) {
  std::vector<Point> points;
  for (const LabelledVertex& v : cell) points.push_back(v.point);
  return points;
}

// Every cell keeps an area, and every edge labelled with a neighbour j faces one edge of j
// labelled back.
void check_faces(const std::vector<LabelledPolygon>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells[i].size() < 3 || signed_area(points_of(cells[i])) <= 0)
      throw std::invalid_argument("tessellation: sub-block " + std::to_string(i) + " is degenerate");
    for (const LabelledVertex& v : cells[i]) {
      if (v.source < 0) continue;
      const LabelledPolygon& other = cells[static_cast<std::size_t>(v.source)];
      const auto back = std::count_if(other.begin(), other.end(),
                                      [&](const LabelledVertex& w) { return w.source == static_cast<int>(i); });
      if (back != 1)
        throw std::invalid_argument("tessellation: the face between sub-blocks " + std::to_string(i) + " and " +
                                    std::to_string(v.source) + " is not shared");
    }
  }
}

// Each cell as triangles fanned from its centroid: triangle k of cell c has the cell's edge k,
// then the spokes to triangles k + 1 and k − 1. A face between cells becomes a face between
// the triangles on it.
Tessellation fan_into_triangles(const std::vector<LabelledPolygon>& cells) {
  std::vector<int> first(cells.size() + 1, 0);
  for (std::size_t c = 0; c < cells.size(); ++c) first[c + 1] = first[c] + static_cast<int>(cells[c].size());
  // The triangle of cell `c` on its edge facing cell `from`.
  const auto facing = [&](int c, int from) {
    const LabelledPolygon& cell = cells[static_cast<std::size_t>(c)];
    for (std::size_t k = 0; k < cell.size(); ++k)
      if (cell[k].source == from) return first[static_cast<std::size_t>(c)] + static_cast<int>(k);
    return -1;  // check_faces has made sure of it
  };
  Tessellation out;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const LabelledPolygon& cell = cells[c];
    const std::vector<Point> points = points_of(cell);
    const Point middle = centroid(points);
    const int n = static_cast<int>(cell.size());
    for (int k = 0; k < n; ++k) {
      const int source = cell[static_cast<std::size_t>(k)].source;
      out.cells.push_back({points[static_cast<std::size_t>(k)], points[static_cast<std::size_t>((k + 1) % n)], middle});
      out.edge_sources.push_back({source < 0 ? source : facing(source, static_cast<int>(c)),
                                  first[c] + (k + 1) % n, first[c] + (k + n - 1) % n});
    }
  }
  return out;
}

}  // namespace

std::vector<Point> generate_seeds(const Box& box, double size, std::uint64_t seed) {
  if (!(size > 0)) throw std::invalid_argument("tessellation: the size must be > 0");
  PortableRandom random(seed);
  std::vector<Point> seeds;
  const long long columns = static_cast<long long>(std::ceil(box.width() / size));
  const long long rows = static_cast<long long>(std::ceil(box.height() / size));
  for (long long j = 0; j < rows; ++j)
    for (long long i = 0; i < columns; ++i) {
      const double u = random.uniform();
      const double v = random.uniform();
      seeds.push_back({box.lo.x + (static_cast<double>(i) + u) * size, box.lo.y + (static_cast<double>(j) + v) * size});
    }
  return seeds;
}

CrackSeeds make_crack_seeds(const Segment2& crack, double spacing) {
  const double length = distance(crack.from, crack.to);
  if (!(spacing > 0) || !(length > 0)) throw std::invalid_argument("tessellation: a crack needs a length and a spacing");
  const double pairs = std::max(2.0, std::round(length / spacing));
  CrackSeeds out;
  out.spacing = length / pairs;
  const Point t = (crack.to - crack.from) / length;
  const Point n{-t.y, t.x};
  const auto count = static_cast<int>(pairs);
  for (int k = -2; k < count + 2; ++k) {
    const Point on_line = crack.from + ((static_cast<double>(k) + 0.5) * out.spacing) * t;
    out.seeds.push_back(on_line + (0.5 * out.spacing) * n);
    out.seeds.push_back(on_line - (0.5 * out.spacing) * n);
  }
  return out;
}

bool lies_near_crack(Point p, const Segment2& crack, double spacing) {
  const double length = distance(crack.from, crack.to);
  const Point t = (crack.to - crack.from) / length;
  return distance_to_segment(p, crack.from - (2.0 * spacing) * t, crack.to + (2.0 * spacing) * t) < spacing;
}

bool lies_on_crack(Point a, Point b, const Segment2& crack, double tolerance) {
  const double length = distance(crack.from, crack.to);
  const Point t = (crack.to - crack.from) / length;
  const auto off_line = [&](Point p) { return std::abs(cross(t, p - crack.from)); };
  if (off_line(a) > tolerance || off_line(b) > tolerance) return false;
  const double along = dot(0.5 * (a + b) - crack.from, t);
  return along > 0.0 && along < length;
}

std::vector<Point> select_seeds(std::span<const Point> polygon, std::span<const Point> seeds, double margin) {
  std::vector<Point> out;
  const std::size_t n = polygon.size();
  for (Point s : seeds) {
    if (!contains(polygon, s)) continue;
    bool clear = true;
    for (std::size_t k = 0; k < n && clear; ++k) clear = distance_to_segment(s, polygon[k], polygon[(k + 1) % n]) >= margin;
    if (clear) out.push_back(s);
  }
  return out;
}

Tessellation tessellate_convex(std::span<const Point> polygon, std::span<const Point> seeds, double size,
                               TessellationKind kind) {
  if (!(size > 0)) throw std::invalid_argument("tessellation: the size must be > 0");
  const std::size_t n = polygon.size();
  if (n < 3 || signed_area(polygon) <= 0) throw std::invalid_argument("tessellation: the polygon must be counter-clockwise");
  for (std::size_t k = 0; k < n; ++k)
    if (orient(polygon[k], polygon[(k + 1) % n], polygon[(k + 2) % n]) < -1e-12 * size * size)
      throw std::invalid_argument("tessellation: the polygon is not convex");
  const SeedGrid grid(seeds, size);
  std::vector<LabelledPolygon> cells;
  for (std::size_t i = 0; i < seeds.size(); ++i) cells.push_back(make_voronoi_cell(polygon, seeds, grid, static_cast<int>(i), size));
  weld_vertices(cells, 1e-2 * size);
  check_faces(cells);
  if (kind == TessellationKind::triangles) return fan_into_triangles(cells);
  Tessellation out;
  for (const LabelledPolygon& c : cells) {
    Polygon p;
    std::vector<int> sources;
    for (const LabelledVertex& v : c) {
      p.push_back(v.point);
      sources.push_back(v.source);
    }
    out.cells.push_back(std::move(p));
    out.edge_sources.push_back(std::move(sources));
  }
  return out;
}

}  // namespace hydrodda::geometry
