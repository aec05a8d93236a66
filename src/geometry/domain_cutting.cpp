#include "geometry/domain_cutting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "geometry/spatial_grid.hpp"

namespace hydrodda::geometry {

namespace {

struct Piece {
  Point a;
  Point b;
  int fracture = -1;  // -1: a domain edge
};

// Points closer than `tolerance` are one vertex: a new point takes the first vertex added
// within the tolerance, found in the 3 × 3 cells of a hash grid of cells `tolerance` wide
// (the first of several: the same vertex a scan of every point in order would give).
class VertexPool {
 public:
  explicit VertexPool(double tolerance) : tolerance_(tolerance) {}
  int add(Point p) {
    const std::int64_t cx = cell(p.x), cy = cell(p.y);
    int found = -1;
    for (std::int64_t i = cx - 1; i <= cx + 1; ++i)
      for (std::int64_t j = cy - 1; j <= cy + 1; ++j) {
        const auto it = cells_.find(key(i, j));
        if (it == cells_.end()) continue;
        for (int v : it->second)
          if (distance(points_[v], p) <= tolerance_ && (found < 0 || v < found)) found = v;
      }
    if (found >= 0) return found;
    points_.push_back(p);
    const int id = static_cast<int>(points_.size() - 1);
    cells_[key(cx, cy)].push_back(id);
    return id;
  }
  const std::vector<Point>& points() const { return points_; }

 private:
  std::int64_t cell(double x) const { return static_cast<std::int64_t>(std::floor(x / tolerance_)); }
  static std::uint64_t key(std::int64_t i, std::int64_t j) {
    return static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(j);
  }
  double tolerance_;
  std::vector<Point> points_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;  // looked up only, never iterated
};

using EdgeMap = std::map<std::pair<int, int>, int>;  // (low, high) vertex ids → fracture id (or -1)

// The pieces split where they meet, as edges between pooled vertices.
EdgeMap split_pieces(const std::vector<Piece>& pieces, VertexPool& pool, double tolerance) {
  std::vector<Box> boxes;
  boxes.reserve(pieces.size());
  for (const Piece& p : pieces) {
    Box box;
    box.add(p.a);
    box.add(p.b);
    boxes.push_back(box.inflated(tolerance));
  }
  const SpatialGrid grid(boxes);
  EdgeMap edges;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& s = pieces[i];
    const auto parameter_of = [&](Point e) {
      return std::clamp(dot(e - s.a, s.b - s.a) / dot(s.b - s.a, s.b - s.a), 0.0, 1.0);
    };
    std::vector<double> cuts{0.0, 1.0};
    grid.for_each_overlap(boxes[i], [&](int j) {
      if (static_cast<std::size_t>(j) == i) return;
      const Piece& o = pieces[j];
      if (segments_intersect(s.a, s.b, o.a, o.b)) {
        if (auto t = line_intersection_parameter(s.a, s.b, o.a, o.b)) {
          cuts.push_back(std::clamp(*t, 0.0, 1.0));
        } else {  // collinear overlap: cut at the other's ends where they lie on this piece
          for (Point e : {o.a, o.b})
            if (distance_to_segment(e, s.a, s.b) <= tolerance) cuts.push_back(parameter_of(e));
        }
      }
      // Ends of other pieces lying on this one (T-junctions within tolerance) also cut it.
      for (Point e : {o.a, o.b})
        if (distance_to_segment(e, s.a, s.b) <= tolerance) cuts.push_back(parameter_of(e));
    });
    std::sort(cuts.begin(), cuts.end());
    int previous = pool.add(s.a);
    for (std::size_t k = 1; k < cuts.size(); ++k) {
      const int v = (k + 1 == cuts.size()) ? pool.add(s.b) : pool.add(s.a + cuts[k] * (s.b - s.a));
      if (v != previous) edges.emplace(std::minmax(previous, v), s.fracture);
      previous = v;
    }
  }
  return edges;
}

// Removes edges with an end of degree 1, repeatedly; the fractures that lost one, appended.
void drop_dangling(EdgeMap& edges, std::size_t point_count, std::vector<int>& dropped) {
  std::vector<int> degree(point_count, 0);
  for (const auto& [e, f] : edges) {
    ++degree[e.first];
    ++degree[e.second];
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (auto it = edges.begin(); it != edges.end();) {
      if (degree[it->first.first] <= 1 || degree[it->first.second] <= 1) {
        --degree[it->first.first];
        --degree[it->first.second];
        dropped.push_back(it->second);
        it = edges.erase(it);
        changed = true;
      } else {
        ++it;
      }
    }
  }
}

// Removes edges not connected to the domain boundary (its edges carry fracture id −1).
void drop_islands(EdgeMap& edges, std::size_t point_count, std::vector<int>& dropped) {
  std::vector<std::vector<int>> neighbours(point_count);
  std::vector<int> stack;
  std::vector<bool> reached(point_count, false);
  for (const auto& [e, f] : edges) {
    neighbours[e.first].push_back(e.second);
    neighbours[e.second].push_back(e.first);
    if (f < 0)
      for (int v : {e.first, e.second})
        if (!reached[v]) {
          reached[v] = true;
          stack.push_back(v);
        }
  }
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (int w : neighbours[v])
      if (!reached[w]) {
        reached[w] = true;
        stack.push_back(w);
      }
  }
  for (auto it = edges.begin(); it != edges.end();) {
    if (!reached[it->first.first]) {
      dropped.push_back(it->second);
      it = edges.erase(it);
    } else {
      ++it;
    }
  }
}

// The faces of the arrangement: half-edge h runs half[h].first → half[h].second, its twin is
// h ^ 1, and face_of[h] is the face on its left.
struct Faces {
  std::vector<std::pair<int, int>> half;
  std::vector<int> half_fracture;
  std::vector<int> face_of;
  std::vector<std::vector<int>> loops;  // each face's half-edges in order
};

Faces walk_faces(const EdgeMap& edges, const std::vector<Point>& points) {
  Faces f;
  for (const auto& [e, fracture] : edges) {
    f.half.push_back({e.first, e.second});
    f.half.push_back({e.second, e.first});
    f.half_fracture.push_back(fracture);
    f.half_fracture.push_back(fracture);
  }
  // Outgoing half-edges around each vertex sorted counter-clockwise by angle.
  std::vector<std::vector<int>> around(points.size());
  for (std::size_t h = 0; h < f.half.size(); ++h) around[f.half[h].first].push_back(static_cast<int>(h));
  const auto angle = [&](int h) {
    const Point d = points[f.half[h].second] - points[f.half[h].first];
    return std::atan2(d.y, d.x);
  };
  std::vector<int> position(f.half.size());
  for (auto& list : around) {
    std::sort(list.begin(), list.end(), [&](int a, int b) { return angle(a) < angle(b); });
    for (std::size_t k = 0; k < list.size(); ++k) position[list[k]] = static_cast<int>(k);
  }
  f.face_of.assign(f.half.size(), -1);
  for (std::size_t start = 0; start < f.half.size(); ++start) {
    if (f.face_of[start] >= 0) continue;
    const int face = static_cast<int>(f.loops.size());
    std::vector<int> loop;
    int h = static_cast<int>(start);
    while (f.face_of[h] < 0) {
      f.face_of[h] = face;
      loop.push_back(h);
      const int twin = h ^ 1;
      const auto& list = around[f.half[twin].first];
      const int k = position[twin];
      h = list[(k - 1 + static_cast<int>(list.size())) % static_cast<int>(list.size())];
    }
    f.loops.push_back(std::move(loop));
  }
  return f;
}

}  // namespace

CutResult cut_domain(const Polygon& domain, const std::vector<Segment2>& fractures, const std::vector<Polygon>& welded) {
  CutResult result;
  const Box box = bounding_box(domain);
  const double tolerance = 1e-9 * std::max(box.width(), box.height());

  // 1. Pieces: domain edges, and fracture parts inside the domain and outside welded regions.
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < domain.size(); ++i) pieces.push_back({domain[i], domain[(i + 1) % domain.size()], -1});
  for (std::size_t f = 0; f < fractures.size(); ++f) {
    const Point from = fractures[f].from, to = fractures[f].to;
    for (auto [t0, t1] : clip_segment_to_polygon(from, to, domain)) {
      std::vector<std::pair<Point, Point>> current{{from + t0 * (to - from), from + t1 * (to - from)}};
      for (const Polygon& w : welded) {
        std::vector<std::pair<Point, Point>> next;
        for (auto [p, q] : current)
          for (auto [s0, s1] : clip_segment_to_polygon(p, q, w, false)) next.push_back({p + s0 * (q - p), p + s1 * (q - p)});
        current = std::move(next);
      }
      for (auto [a, b] : current) pieces.push_back({a, b, static_cast<int>(f)});
    }
  }

  // 2. Split at intersections; snap to shared vertices.
  VertexPool pool(tolerance);
  EdgeMap edges = split_pieces(pieces, pool, tolerance);
  const std::vector<Point>& points = pool.points();

  // 3. Drop what separates nothing, until every edge has a different face on each side.
  std::vector<int> dropped;
  Faces faces;
  const auto drop_half_edge = [&](int h) {
    const auto [u, v] = faces.half[h];
    if (edges.erase(std::minmax(u, v)) > 0) dropped.push_back(faces.half_fracture[h]);
  };
  for (;;) {
    drop_dangling(edges, points.size(), dropped);
    drop_islands(edges, points.size(), dropped);
    faces = walk_faces(edges, points);
    bool changed = false;
    for (std::size_t h = 0; h < faces.half.size(); h += 2) {
      if (faces.face_of[h] != faces.face_of[h + 1]) continue;
      drop_half_edge(static_cast<int>(h));
      changed = true;
    }
    if (changed) continue;
    // A face that passes a vertex twice goes round a cluster of blocks that touches the rest
    // only there: its walk from the first pass to the second (or the rest) turns clockwise,
    // round the cluster. The face would be a block with a hole, pinched at the vertex: the
    // cluster is dropped like an island (its boundary here, then its inside as an island).
    // Every such face is dropped in the same round, but for one that lost an edge to another's
    // drop, which waits for the next round's faces: a face whose edges all remain is the same
    // face next round, walked from the same start, and what a drop makes an island is dropped
    // either way, so the edges dropped in the end are those of dropping one face a round.
    std::vector<bool> gone(faces.half.size() / 2, false);
    for (const std::vector<int>& loop : faces.loops) {
      if (std::any_of(loop.begin(), loop.end(), [&](int h) { return gone[h / 2]; })) continue;
      Polygon walk;
      for (int h : loop) walk.push_back(points[faces.half[h].first]);
      if (signed_area(walk) <= 0.0) continue;  // the outer face
      std::map<int, std::size_t> first_pass;
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const auto [it, fresh] = first_pass.emplace(faces.half[loop[k]].first, k);
        if (fresh) continue;
        const Polygon part(walk.begin() + static_cast<std::ptrdiff_t>(it->second), walk.begin() + static_cast<std::ptrdiff_t>(k));
        const bool part_goes_round = signed_area(part) < 0.0;
        for (std::size_t m = 0; m < loop.size(); ++m)
          if ((m >= it->second && m < k) == part_goes_round) {
            drop_half_edge(loop[m]);
            gone[loop[m] / 2] = true;
          }
        changed = true;
        break;
      }
    }
    if (!changed) break;
  }
  std::sort(dropped.begin(), dropped.end());
  dropped.erase(std::unique(dropped.begin(), dropped.end()), dropped.end());
  for (int f : dropped)
    if (f >= 0) {
      result.dropped_from.push_back(f);
      result.warnings.push_back("fracture " + std::to_string(f) + ": a piece of it separates no blocks and is dropped");
    }
  for (const auto& [e, f] : edges)
    if (f >= 0) result.used_traces.push_back({points[e.first], points[e.second]});

  // 4. The bounded faces are the blocks.
  struct Block {
    Polygon polygon;
    std::vector<int> fractures;
    Point centroid;
  };
  std::vector<Block> blocks;
  for (const std::vector<int>& loop : faces.loops) {
    Block b;
    for (int h : loop) {
      b.polygon.push_back(points[faces.half[h].first]);
      b.fractures.push_back(faces.half_fracture[h]);
    }
    if (signed_area(b.polygon) <= 0.0) continue;
    b.centroid = centroid(b.polygon);
    blocks.push_back(std::move(b));
  }
  // Deterministic order: by centroid, bottom to top, then left to right.
  std::sort(blocks.begin(), blocks.end(), [](const Block& a, const Block& b) {
    return a.centroid.y != b.centroid.y ? a.centroid.y < b.centroid.y : a.centroid.x < b.centroid.x;
  });
  for (Block& b : blocks) {
    result.blocks.push_back(std::move(b.polygon));
    result.edge_fractures.push_back(std::move(b.fractures));
  }
  return result;
}

std::optional<ShrunkBlock> shrink_block(const Polygon& p, const std::vector<bool>& fracture_face, double aperture) {
  // Each edge as its line moved inward: through a + offset · normal, along b − a.
  struct Line {
    Point a, b;
    Point normal;  // inward unit normal
    double offset;
    int edge;
  };
  const std::size_t n = p.size();
  std::vector<Line> lines;
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = p[i], b = p[(i + 1) % n];
    const Point t = (b - a) / distance(a, b);
    lines.push_back({a, b, {-t.y, t.x}, fracture_face[i] ? 0.5 * aperture : 0.0, static_cast<int>(i)});
  }
  // Where the moved lines of `before` and `after` meet; on collinear lines, the start of `after` moved.
  const auto meet = [](const Line& before, const Line& after) {
    const Point a0 = before.a + before.offset * before.normal, a1 = before.b + before.offset * before.normal;
    const Point b0 = after.a + after.offset * after.normal, b1 = after.b + after.offset * after.normal;
    const auto t = line_intersection_parameter(a0, a1, b0, b1);
    const double turn = std::abs(cross(a1 - a0, b1 - b0)) / (distance(a0, a1) * distance(b0, b1));
    if (t && turn > 1e-9) return a0 + *t * (a1 - a0);
    return after.a + std::max(before.offset, after.offset) * after.normal;
  };
  for (;;) {
    const std::size_t m = lines.size();
    if (m < 3) return std::nullopt;
    Polygon shrunk(m);
    for (std::size_t k = 0; k < m; ++k) shrunk[k] = meet(lines[(k + m - 1) % m], lines[k]);
    // The edge turned furthest around, relative to its length, is removed first.
    std::optional<std::size_t> reversed;
    double worst = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      const Point original = lines[k].b - lines[k].a;
      const double along = dot(shrunk[(k + 1) % m] - shrunk[k], original) / dot(original, original);
      if (along <= 0.0 && (!reversed || along < worst)) {
        reversed = k;
        worst = along;
      }
    }
    if (reversed) {
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(*reversed));
      continue;
    }
    if (signed_area(shrunk) <= 0.0 || find_self_intersection(shrunk).has_value()) return std::nullopt;
    ShrunkBlock out;
    out.polygon = std::move(shrunk);
    for (const Line& l : lines) out.edges.push_back(l.edge);
    return out;
  }
}

std::vector<Polygon> shrink_blocks(const std::vector<Polygon>& blocks, const Polygon& domain, double aperture) {
  if (aperture <= 0.0) return blocks;
  const Box box = bounding_box(domain);
  const double tolerance = 1e-9 * std::max(box.width(), box.height());
  const auto on_boundary = [&](Point p) {
    for (std::size_t i = 0; i < domain.size(); ++i)
      if (distance_to_segment(p, domain[i], domain[(i + 1) % domain.size()]) <= tolerance) return true;
    return false;
  };
  std::vector<Polygon> out;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Polygon& p = blocks[b];
    const std::size_t n = p.size();
    std::vector<bool> fracture_face(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = p[i], c = p[(i + 1) % n];
      fracture_face[i] = !(on_boundary(a) && on_boundary(c) && on_boundary(0.5 * (a + c)));
    }
    auto shrunk = shrink_block(p, fracture_face, aperture);
    if (!shrunk)
      throw std::runtime_error("block " + std::to_string(b + 1) + " is too small for an initial aperture of " +
                               std::to_string(aperture) + " m");
    out.push_back(std::move(shrunk->polygon));
  }
  return out;
}

}  // namespace hydrodda::geometry
