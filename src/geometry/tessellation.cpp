#include "geometry/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/convex_decomposition.hpp"
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

// The outline's edges labelled −1 − k, as a tessellated polygon's.
LabelledPolygon label_outline(std::span<const Point> polygon) {
  LabelledPolygon out;
  for (std::size_t k = 0; k < polygon.size(); ++k) out.push_back({polygon[k], -1 - static_cast<int>(k)});
  return out;
}

// The Voronoi cell of seed i clipped to the convex `region`, whose labels it keeps.
LabelledPolygon make_voronoi_cell(const LabelledPolygon& region, std::span<const Point> seeds, const SeedGrid& grid,
                                  int i, double size) {
  const Point s = seeds[static_cast<std::size_t>(i)];
  double radius = 3.0 * size;
  for (;;) {
    LabelledPolygon cell = region;
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
// position, that of the member most tied to the polygon (its tie), the first
// of those (in cell and vertex order). Then each cell drops the edges that joined two
// vertices of one group, keeping the labels of the edges that remain. A polygon's corner
// welded to a bisector's crossing of an edge beside it would move off the other edge, and
// the sub-blocks would no longer fill the polygon: their faces there would stand up to
// `tolerance` off the neighbouring block's, and carry nothing of the stress across them.
// `ties`: of each vertex, cell by cell (count_polygon_edges_at, or a finer count).
void weld_vertices(std::vector<LabelledPolygon>& cells, const std::vector<int>& ties, double tolerance) {
  std::vector<Point> points;
  for (const LabelledPolygon& c : cells)
    for (const LabelledVertex& v : c) points.push_back(v.point);
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

// The edges of cell j labelled i that run along cell i's edge k the other way (the same ends).
int count_faces_back(const std::vector<LabelledPolygon>& cells, std::size_t i, std::size_t k) {
  const LabelledPolygon& cell = cells[i];
  const LabelledPolygon& other = cells[static_cast<std::size_t>(cell[k].source)];
  int count = 0;
  for (std::size_t f = 0; f < other.size(); ++f)
    count += other[f].source == static_cast<int>(i) && other[f].point == cell[(k + 1) % cell.size()].point &&
             other[(f + 1) % other.size()].point == cell[k].point;
  return count;
}

// Every cell keeps an area, and every edge labelled with a neighbour j faces one edge of j
// labelled back: the only one (a convex polygon's cells meet along one face), or, where two
// sub-blocks meet along two faces (beside a reflex corner), the one with the same ends.
void check_faces(const std::vector<LabelledPolygon>& cells, bool by_segment = false) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells[i].size() < 3 || signed_area(points_of(cells[i])) <= 0)
      throw std::invalid_argument("tessellation: sub-block " + std::to_string(i) + " is degenerate");
    for (std::size_t k = 0; k < cells[i].size(); ++k) {
      const LabelledVertex& v = cells[i][k];
      if (v.source < 0) continue;
      const LabelledPolygon& other = cells[static_cast<std::size_t>(v.source)];
      const auto back = by_segment ? count_faces_back(cells, i, k)
                                   : std::count_if(other.begin(), other.end(), [&](const LabelledVertex& w) {
                                       return w.source == static_cast<int>(i);
                                     });
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
  // The triangle of cell `c` on its edge facing cell `from` along b → a: the one with those
  // ends, else the only one facing `from` (check_faces has made sure of one or the other).
  const auto facing = [&](int c, int from, Point a, Point b) {
    const LabelledPolygon& cell = cells[static_cast<std::size_t>(c)];
    int any = -1;
    for (std::size_t k = 0; k < cell.size(); ++k) {
      if (cell[k].source != from) continue;
      if (cell[k].point == b && cell[(k + 1) % cell.size()].point == a) return first[static_cast<std::size_t>(c)] + static_cast<int>(k);
      if (any < 0) any = first[static_cast<std::size_t>(c)] + static_cast<int>(k);
    }
    return any;
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
      out.cell_of.push_back(static_cast<int>(c));
      out.edge_sources.push_back({source < 0 ? source
                                             : facing(source, static_cast<int>(c), points[static_cast<std::size_t>(k)],
                                                      points[static_cast<std::size_t>((k + 1) % n)]),
                                  first[c] + (k + 1) % n, first[c] + (k + n - 1) % n});
    }
  }
  return out;
}

// The ties of count_polygon_edges_at, cell by cell.
std::vector<int> ties_by_outline_edges(const std::vector<LabelledPolygon>& cells) {
  std::vector<int> ties;
  for (const LabelledPolygon& c : cells)
    for (std::size_t k = 0; k < c.size(); ++k) ties.push_back(count_polygon_edges_at(c, k));
  return ties;
}

Tessellation to_tessellation(const std::vector<LabelledPolygon>& cells, TessellationKind kind) {
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
    out.cell_of.push_back(static_cast<int>(out.cell_of.size()));
  }
  return out;
}

bool is_convex_polygon(std::span<const Point> polygon, double size) {
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k)
    if (orient(polygon[k], polygon[(k + 1) % n], polygon[(k + 2) % n]) < -1e-12 * size * size) return false;
  return true;
}

Tessellation tessellate_convex_polygon(std::span<const Point> polygon, std::span<const Point> seeds, double size,
                                       TessellationKind kind) {
  const SeedGrid grid(seeds, size);
  const LabelledPolygon outline = label_outline(polygon);
  std::vector<LabelledPolygon> cells;
  for (std::size_t i = 0; i < seeds.size(); ++i) cells.push_back(make_voronoi_cell(outline, seeds, grid, static_cast<int>(i), size));
  weld_vertices(cells, ties_by_outline_edges(cells), 1e-2 * size);
  check_faces(cells);
  return to_tessellation(cells, kind);
}

// The seeds' Voronoi cells clipped to each convex piece of a polygon: one fragment per seed
// and piece it meets, seed by seed. Its edges are labelled: on the outline, −1 − k; on a
// bisector, the other seed's fragment in the same piece; on a seam, the same seed's fragment
// in the piece across; kNoFragment where that fragment is empty (a face of no length, which
// the welding drops).
constexpr int kNoFragment = std::numeric_limits<int>::min();

struct Fragments {
  std::vector<LabelledPolygon> cells;
  std::vector<int> seed_of;
};

// Piece p's edges labelled: −1 − k on the polygon's edge k, `seams` + q on the seam with piece q.
LabelledPolygon label_piece(std::span<const Point> polygon, const std::vector<std::vector<int>>& pieces, std::size_t p,
                            int seams) {
  const auto n = static_cast<int>(polygon.size());
  LabelledPolygon out;
  const std::vector<int>& piece = pieces[p];
  for (std::size_t k = 0; k < piece.size(); ++k) {
    const int a = piece[k], b = piece[(k + 1) % piece.size()];
    int label = -1 - a;
    if (b != (a + 1) % n)
      for (std::size_t q = 0; q < pieces.size(); ++q)
        for (std::size_t m = 0; m < pieces[q].size(); ++m)
          if (pieces[q][m] == b && pieces[q][(m + 1) % pieces[q].size()] == a) label = seams + static_cast<int>(q);
    out.push_back({polygon[static_cast<std::size_t>(a)], label});
  }
  return out;
}

Fragments clip_cells_to_pieces(std::span<const Point> polygon, const std::vector<std::vector<int>>& pieces,
                               std::span<const Point> seeds, double size) {
  const SeedGrid grid(seeds, size);
  const auto seams = static_cast<int>(seeds.size());
  std::vector<LabelledPolygon> regions;
  for (std::size_t p = 0; p < pieces.size(); ++p) regions.push_back(label_piece(polygon, pieces, p, seams));
  Fragments out;
  std::vector<int> piece_of;
  std::vector<int> index(seeds.size() * pieces.size(), kNoFragment);  // of seed i's fragment in piece p: i · pieces + p
  for (std::size_t i = 0; i < seeds.size(); ++i)
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      LabelledPolygon cell = make_voronoi_cell(regions[p], seeds, grid, static_cast<int>(i), size);
      if (cell.size() < 3) continue;
      index[i * pieces.size() + p] = static_cast<int>(out.cells.size());
      out.cells.push_back(std::move(cell));
      out.seed_of.push_back(static_cast<int>(i));
      piece_of.push_back(static_cast<int>(p));
    }
  for (std::size_t f = 0; f < out.cells.size(); ++f)
    for (LabelledVertex& v : out.cells[f]) {
      if (v.source < 0) continue;
      const bool seam = v.source >= seams;
      const auto seed = static_cast<std::size_t>(seam ? out.seed_of[f] : v.source);
      const auto piece = static_cast<std::size_t>(seam ? v.source - seams : piece_of[f]);
      v.source = index[seed * pieces.size() + piece];
    }
  return out;
}

// Union–find over fragments: a merged group's polygon is kept at its root.
class FragmentGroups {
 public:
  explicit FragmentGroups(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0); }
  int root(int f) {
    while (parent_[static_cast<std::size_t>(f)] != f) f = parent_[static_cast<std::size_t>(f)];
    return f;
  }
  void join(int root, int into) { parent_[static_cast<std::size_t>(root)] = into; }

 private:
  std::vector<int> parent_;
};

// Labels as the roots of their groups (outline labels and kNoFragment kept).
LabelledPolygon with_roots(LabelledPolygon cell, FragmentGroups& groups) {
  for (LabelledVertex& v : cell)
    if (v.source >= 0) v.source = groups.root(v.source);
  return cell;
}

bool turns_straight(Point a, Point b, Point c) {
  return std::abs(orient(a, b, c)) <= 1e-12 * distance(a, b) * distance(b, c);
}

// Whether the cell (labels as roots) is convex and meets each neighbour along one straight
// run of edges (a merged neighbour along its two parts' faces, in line).
bool is_convex_with_one_face_each(const LabelledPolygon& cell) {
  const std::size_t n = cell.size();
  std::map<int, int> runs;
  for (std::size_t k = 0; k < n; ++k) {
    const LabelledVertex& before = cell[(k + n - 1) % n];
    const LabelledVertex& at = cell[k];
    const LabelledVertex& after = cell[(k + 1) % n];
    if (!turns_left_or_straight(before.point, at.point, after.point)) return false;
    const bool continues = before.source == at.source && turns_straight(before.point, at.point, after.point);
    if (at.source >= 0 && !continues && ++runs[at.source] > 1) return false;
  }
  return true;
}

// Cells a and b (labels as roots) joined across their one shared face, a's k → k + 1 being
// b's m + 1 → m (its ends within `tolerance`: each side computed its crossings of the seam):
// a from k + 1 round to k, then b past m + 1 round to m − 1. Empty when they share no single face.
LabelledPolygon join_across(const LabelledPolygon& a, const LabelledPolygon& b, int a_root, int b_root,
                            double tolerance) {
  const auto face_to = [](const LabelledPolygon& c, int other) {
    std::size_t found = c.size();
    for (std::size_t k = 0; k < c.size(); ++k)
      if (c[k].source == other) {
        if (found != c.size()) return c.size();
        found = k;
      }
    return found;
  };
  const std::size_t k = face_to(a, b_root), m = face_to(b, a_root);
  if (k == a.size() || m == b.size()) return {};
  if (distance(a[k].point, b[(m + 1) % b.size()].point) > tolerance ||
      distance(a[(k + 1) % a.size()].point, b[m].point) > tolerance)
    return {};
  LabelledPolygon out;
  for (std::size_t j = 1; j < a.size(); ++j) out.push_back(a[(k + j) % a.size()]);
  out.push_back({a[k].point, b[(m + 1) % b.size()].source});
  for (std::size_t j = 2; j < b.size(); ++j) out.push_back(b[(m + j) % b.size()]);
  return out;
}

// Fragments of one seed across a seam merged where their union is convex, every neighbour then
// met along one face; the rest stay apart, bonded along the seam. Merged-away cells are left
// empty, the labels as the groups' roots.
std::vector<LabelledPolygon> merge_convex_unions(Fragments fragments, double size) {
  std::vector<LabelledPolygon>& cells = fragments.cells;
  FragmentGroups groups(cells.size());
  // Until no merge is left: a pair that could not merge may once one of them has grown.
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < cells.size(); ++a) {
      for (std::size_t k = 0; k < cells[a].size(); ++k) {
        const int across = cells[a][k].source;
        if (across < 0 || fragments.seed_of[static_cast<std::size_t>(across)] != fragments.seed_of[a]) continue;
        const int b = groups.root(across);
        if (b == static_cast<int>(a)) continue;
        const LabelledPolygon joined =
            with_roots(join_across(with_roots(cells[a], groups), with_roots(cells[static_cast<std::size_t>(b)], groups),
                                   static_cast<int>(a), b, 1e-9 * size),
                       groups);
        if (joined.empty() || !is_convex_with_one_face_each(joined)) continue;
        cells[a] = joined;
        cells[static_cast<std::size_t>(b)].clear();
        groups.join(b, static_cast<int>(a));
        merged = true;
        k = 0;  // the grown cell's faces from the start
      }
    }
  }
  for (LabelledPolygon& c : cells) c = with_roots(c, groups);
  return cells;
}

// The cells without the empty ones, renumbered, each without the vertex between two edges
// that face one neighbour in line. Throws where a face names an empty cell, its own or none.
std::vector<LabelledPolygon> compact(const std::vector<LabelledPolygon>& cells) {
  std::vector<int> renumbered(cells.size(), kNoFragment);
  int next = 0;
  for (std::size_t f = 0; f < cells.size(); ++f)
    if (!cells[f].empty()) renumbered[f] = next++;
  std::vector<LabelledPolygon> out;
  for (std::size_t f = 0; f < cells.size(); ++f) {
    const LabelledPolygon& cell = cells[f];
    if (cell.empty()) continue;
    LabelledPolygon kept;
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const LabelledVertex& before = cell[(k + cell.size() - 1) % cell.size()];
      const bool one_neighbour = before.source == cell[k].source && cell[k].source >= 0;
      if (one_neighbour || (before.source == cell[k].source &&
                            turns_straight(before.point, cell[k].point, cell[(k + 1) % cell.size()].point)))
        continue;
      kept.push_back(cell[k]);
      if (cell[k].source < 0 && cell[k].source != kNoFragment) continue;
      const int other = cell[k].source == kNoFragment ? kNoFragment : renumbered[static_cast<std::size_t>(cell[k].source)];
      if (other == kNoFragment || other == renumbered[f])
        throw std::invalid_argument("tessellation: a face of sub-block " + std::to_string(out.size()) +
                                    " has no other sub-block behind it");
      kept.back().source = other;
    }
    out.push_back(std::move(kept));
  }
  return out;
}

// A cell the welding left as two vertices (a sliver thinner than its tolerance) is emptied,
// its two neighbours then facing each other (or the outline) where they faced it.
void close_up_slivers(std::vector<LabelledPolygon>& cells) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c].size() != 2) continue;
    const int sides[2] = {cells[c][0].source, cells[c][1].source};
    for (int k = 0; k < 2; ++k) {
      if (sides[k] < 0) continue;
      for (LabelledVertex& v : cells[static_cast<std::size_t>(sides[k])])
        if (v.source == static_cast<int>(c)) v.source = sides[1 - k];
    }
    cells[c].clear();
  }
}

// How firmly each vertex is tied to the polygon: 2 at one of its corners (whatever the edges
// there: where a seam starts, one edge only is on the outline), else the edges at it on the
// outline (count_polygon_edges_at).
std::vector<int> ties_by_corners(const std::vector<LabelledPolygon>& cells, std::span<const Point> polygon) {
  std::vector<int> ties;
  const auto on_outline = [](int source) { return source < 0 && source != kNoFragment; };
  for (const LabelledPolygon& c : cells)
    for (std::size_t k = 0; k < c.size(); ++k) {
      const bool corner = std::find(polygon.begin(), polygon.end(), c[k].point) != polygon.end();
      ties.push_back(corner ? 2 : (on_outline(c[(k + c.size() - 1) % c.size()].source) ? 1 : 0) + (on_outline(c[k].source) ? 1 : 0));
    }
  return ties;
}

// A welded vertex that joined two edges of the outline on either side of one of its corners
// (crossings of those edges nearer each other than the welding's tolerance, the corner itself
// farther) lies off one of them: it goes onto that corner, and the edges it leaves with no
// length go. Throws for one that joined edges of the outline that do not meet.
void snap_onto_corners(std::vector<LabelledPolygon>& cells, std::span<const Point> polygon) {
  const auto n = static_cast<int>(polygon.size());
  const auto outline_edge = [](int source) { return source < 0 && source != kNoFragment ? -1 - source : -1; };
  std::map<std::pair<double, double>, std::vector<int>> edges_at;
  for (const LabelledPolygon& c : cells)
    for (std::size_t k = 0; k < c.size(); ++k)
      for (int source : {c[(k + c.size() - 1) % c.size()].source, c[k].source})
        if (outline_edge(source) >= 0) edges_at[{c[k].point.x, c[k].point.y}].push_back(outline_edge(source));
  std::map<std::pair<double, double>, Point> moves;
  for (auto& [at, edges] : edges_at) {
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    if (edges.size() < 2) continue;
    int before = edges[0], after = edges[1];
    if (after == n - 1 && before == 0) std::swap(before, after);
    if (edges.size() > 2 || (before + 1) % n != after)
      throw std::invalid_argument("tessellation: a vertex welded edges of the polygon that do not meet");
    moves[at] = polygon[static_cast<std::size_t>(after)];
  }
  for (LabelledPolygon& c : cells) {
    for (LabelledVertex& v : c)
      if (const auto move = moves.find({v.point.x, v.point.y}); move != moves.end()) v.point = move->second;
    LabelledPolygon kept;
    for (std::size_t k = 0; k < c.size(); ++k)
      if (!(c[k].point == c[(k + 1) % c.size()].point)) kept.push_back(c[k]);
    c = std::move(kept);
  }
}

Tessellation tessellate_in_convex_pieces(std::span<const Point> polygon, std::span<const Point> seeds, double size,
                                         TessellationKind kind) {
  std::vector<LabelledPolygon> cells =
      compact(merge_convex_unions(clip_cells_to_pieces(polygon, convex_pieces(polygon), seeds, size), size));
  weld_vertices(cells, ties_by_corners(cells, polygon), 1e-2 * size);
  snap_onto_corners(cells, polygon);
  close_up_slivers(cells);
  cells = compact(cells);
  check_faces(cells, true);
  return to_tessellation(cells, kind);
}

// Whether s lies inside the polygon and at least `margin` from its outline.
bool lies_clear_inside(std::span<const Point> polygon, Point s, double margin) {
  if (!contains(polygon, s)) return false;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k)
    if (distance_to_segment(s, polygon[k], polygon[(k + 1) % n]) < margin) return false;
  return true;
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

std::vector<ReflexCornerSeeds> make_reflex_corner_seeds(std::span<const Point> polygon, double size, double margin) {
  const std::size_t n = polygon.size();
  std::vector<ReflexCornerSeeds> out;
  const auto clear_of_earlier = [&](Point s) {
    for (const ReflexCornerSeeds& c : out)
      for (Point t : c.seeds)
        if (distance(s, t) < 0.5 * size) return false;
    return true;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const Point before = polygon[(k + n - 1) % n], at = polygon[k], after = polygon[(k + 1) % n];
    if (turns_left_or_straight(before, at, after)) continue;
    const Point in = (at - before) / distance(at, before), out_edge = (after - at) / distance(after, at);
    // α: from the outgoing edge counter-clockwise to the incoming one, run back (in (π, 2π)).
    double alpha = std::atan2(cross(out_edge, -1.0 * in), dot(out_edge, -1.0 * in));
    if (alpha < 0) alpha += 2.0 * std::numbers::pi;
    const auto at_angle = [&](double angle) {
      const double c = std::cos(angle), s = std::sin(angle);
      return at + (0.5 * size) * Point{c * out_edge.x - s * out_edge.y, s * out_edge.x + c * out_edge.y};
    };
    const ReflexCornerSeeds corner{at, {at_angle(0.25 * alpha), at_angle(0.75 * alpha)}};
    if (std::all_of(corner.seeds.begin(), corner.seeds.end(), [&](Point s) { return lies_clear_inside(polygon, s, margin) && clear_of_earlier(s); }))
      out.push_back(corner);
  }
  return out;
}

std::vector<Point> select_seeds(std::span<const Point> polygon, std::span<const Point> seeds, double margin) {
  std::vector<Point> out;
  for (Point s : seeds)
    if (lies_clear_inside(polygon, s, margin)) out.push_back(s);
  return out;
}

Tessellation tessellate(std::span<const Point> polygon, std::span<const Point> seeds, double size, TessellationKind kind) {
  if (!(size > 0)) throw std::invalid_argument("tessellation: the size must be > 0");
  if (polygon.size() < 3 || signed_area(polygon) <= 0)
    throw std::invalid_argument("tessellation: the polygon must be counter-clockwise");
  if (is_convex_polygon(polygon, size)) return tessellate_convex_polygon(polygon, seeds, size, kind);
  return tessellate_in_convex_pieces(polygon, seeds, size, kind);
}

}  // namespace hydrodda::geometry
