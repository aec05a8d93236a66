#include "geometry/domain_cutting.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

namespace hydrodda::geometry {

namespace {

struct Piece {
  Point a;
  Point b;
  int fracture = -1;  // -1: a domain edge
};

// The parts of segment ab inside the polygon (midpoint test between crossings).
std::vector<std::pair<double, double>> parts_inside(Point a, Point b, const Polygon& polygon, bool keep_inside) {
  std::vector<double> cuts{0.0, 1.0};
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point c = polygon[i], d = polygon[(i + 1) % n];
    if (!segments_intersect(a, b, c, d)) continue;
    if (auto t = line_intersection_parameter(a, b, c, d)) cuts.push_back(std::clamp(*t, 0.0, 1.0));
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] - cuts[i] <= 1e-12) continue;
    const Point mid = a + (0.5 * (cuts[i] + cuts[i + 1])) * (b - a);
    if (contains(polygon, mid) == keep_inside) out.push_back({cuts[i], cuts[i + 1]});
  }
  return out;
}

// Points closer than `tolerance` are one vertex. A linear scan per point: fracture networks of a
// few hundred traces give a few thousand vertices; denser sets would want a grid here (and in
// the pairwise split above it).
class VertexPool {
 public:
  explicit VertexPool(double tolerance) : tolerance_(tolerance) {}
  int add(Point p) {
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (distance(points_[i], p) <= tolerance_) return static_cast<int>(i);
    points_.push_back(p);
    return static_cast<int>(points_.size() - 1);
  }
  const std::vector<Point>& points() const { return points_; }

 private:
  double tolerance_;
  std::vector<Point> points_;
};

}  // namespace

CutResult cut_domain(const Polygon& domain, const std::vector<Segment2>& fractures, const std::vector<Polygon>& welded) {
  CutResult result;
  const Box box = bounding_box(domain);
  const double tolerance = 1e-9 * std::max(box.width(), box.height());

  // 1. Pieces: domain edges, and fracture parts inside the domain and outside welded regions.
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < domain.size(); ++i) pieces.push_back({domain[i], domain[(i + 1) % domain.size()], -1});
  for (std::size_t f = 0; f < fractures.size(); ++f) {
    std::vector<std::pair<Point, Point>> kept;
    for (auto [t0, t1] : parts_inside(fractures[f].from, fractures[f].to, domain, true)) {
      const Point a = fractures[f].from + t0 * (fractures[f].to - fractures[f].from);
      const Point b = fractures[f].from + t1 * (fractures[f].to - fractures[f].from);
      std::vector<std::pair<Point, Point>> current{{a, b}};
      for (const Polygon& w : welded) {
        std::vector<std::pair<Point, Point>> next;
        for (auto [p, q] : current)
          for (auto [s0, s1] : parts_inside(p, q, w, false)) next.push_back({p + s0 * (q - p), p + s1 * (q - p)});
        current = std::move(next);
      }
      kept.insert(kept.end(), current.begin(), current.end());
    }
    for (auto [a, b] : kept) pieces.push_back({a, b, static_cast<int>(f)});
  }

  // 2. Split at intersections; snap to shared vertices.
  VertexPool pool(tolerance);
  std::map<std::pair<int, int>, int> edges;  // (low, high) vertex ids → fracture id (or -1)
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& s = pieces[i];
    std::vector<double> cuts{0.0, 1.0};
    for (std::size_t j = 0; j < pieces.size(); ++j) {
      if (i == j) continue;
      const Piece& o = pieces[j];
      if (!segments_intersect(s.a, s.b, o.a, o.b)) continue;
      if (auto t = line_intersection_parameter(s.a, s.b, o.a, o.b)) {
        cuts.push_back(std::clamp(*t, 0.0, 1.0));
      } else {  // collinear overlap: cut at the other's ends where they lie on this piece
        for (Point e : {o.a, o.b})
          if (distance_to_segment(e, s.a, s.b) <= tolerance)
            cuts.push_back(std::clamp(dot(e - s.a, s.b - s.a) / dot(s.b - s.a, s.b - s.a), 0.0, 1.0));
      }
    }
    // Ends of other pieces lying on this one (T-junctions within tolerance) also cut it.
    for (const Piece& o : pieces)
      for (Point e : {o.a, o.b})
        if (distance_to_segment(e, s.a, s.b) <= tolerance)
          cuts.push_back(std::clamp(dot(e - s.a, s.b - s.a) / dot(s.b - s.a, s.b - s.a), 0.0, 1.0));
    std::sort(cuts.begin(), cuts.end());
    int previous = pool.add(s.a);
    for (std::size_t k = 1; k < cuts.size(); ++k) {
      const int v = (k + 1 == cuts.size()) ? pool.add(s.b) : pool.add(s.a + cuts[k] * (s.b - s.a));
      if (v != previous) edges.emplace(std::minmax(previous, v), s.fracture);
      previous = v;
    }
  }
  const std::vector<Point>& points = pool.points();

  // 3. Drop dangling pieces.
  std::vector<int> degree(points.size(), 0);
  for (const auto& [e, f] : edges) {
    ++degree[e.first];
    ++degree[e.second];
  }
  std::vector<int> dropped_from;  // fractures that lost a piece
  for (bool changed = true; changed;) {
    changed = false;
    for (auto it = edges.begin(); it != edges.end();) {
      if (degree[it->first.first] <= 1 || degree[it->first.second] <= 1) {
        --degree[it->first.first];
        --degree[it->first.second];
        dropped_from.push_back(it->second);
        it = edges.erase(it);
        changed = true;
      } else {
        ++it;
      }
    }
  }
  std::sort(dropped_from.begin(), dropped_from.end());
  dropped_from.erase(std::unique(dropped_from.begin(), dropped_from.end()), dropped_from.end());
  for (int f : dropped_from)
    if (f >= 0)
      result.warnings.push_back("fracture " + std::to_string(f + 1) +
                                ": a piece of it separates no blocks and is dropped");

  // 4. Faces. Outgoing half-edges around each vertex sorted counter-clockwise by angle.
  std::vector<std::vector<int>> around(points.size());
  std::vector<std::pair<int, int>> half;  // half-edge h: from → to; twin is h ^ 1
  for (const auto& [e, f] : edges) {
    half.push_back({e.first, e.second});
    half.push_back({e.second, e.first});
    if (f >= 0) result.used_traces.push_back({points[e.first], points[e.second]});
  }
  for (std::size_t h = 0; h < half.size(); ++h) around[half[h].first].push_back(static_cast<int>(h));
  const auto angle = [&](int h) {
    const Point d = points[half[h].second] - points[half[h].first];
    return std::atan2(d.y, d.x);
  };
  std::vector<int> position(half.size());
  for (auto& list : around) {
    std::sort(list.begin(), list.end(), [&](int a, int b) { return angle(a) < angle(b); });
    for (std::size_t k = 0; k < list.size(); ++k) position[list[k]] = static_cast<int>(k);
  }
  std::vector<bool> visited(half.size(), false);
  for (std::size_t start = 0; start < half.size(); ++start) {
    if (visited[start]) continue;
    Polygon face;
    int h = static_cast<int>(start);
    while (!visited[h]) {
      visited[h] = true;
      face.push_back(points[half[h].first]);
      const int twin = h ^ 1;
      const auto& list = around[half[twin].first];
      const int k = position[twin];
      h = list[(k - 1 + static_cast<int>(list.size())) % static_cast<int>(list.size())];
    }
    if (signed_area(face) > 0.0) result.blocks.push_back(std::move(face));
  }
  // Deterministic order: by centroid, bottom to top, then left to right.
  std::sort(result.blocks.begin(), result.blocks.end(), [](const Polygon& a, const Polygon& b) {
    const Point ca = centroid(a), cb = centroid(b);
    return ca.y != cb.y ? ca.y < cb.y : ca.x < cb.x;
  });
  return result;
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
    // Offset of each edge: 0 on the domain boundary, aperture / 2 on a fracture face.
    std::vector<double> offset(n);
    std::vector<Point> normal(n);  // inward unit normals
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = p[i], c = p[(i + 1) % n];
      const Point t = (c - a) / distance(a, c);
      normal[i] = {-t.y, t.x};
      offset[i] = (on_boundary(a) && on_boundary(c) && on_boundary(0.5 * (a + c))) ? 0.0 : 0.5 * aperture;
    }
    Polygon shrunk(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t prev = (i + n - 1) % n;
      // Lines: (p[prev] + o_prev n_prev) + s t_prev and (p[i] + o_i n_i) + r t_i.
      const Point a0 = p[prev] + offset[prev] * normal[prev];
      const Point a1 = p[i] + offset[prev] * normal[prev];
      const Point b0 = p[i] + offset[i] * normal[i];
      const Point b1 = p[(i + 1) % n] + offset[i] * normal[i];
      const auto t = line_intersection_parameter(a0, a1, b0, b1);
      const double turn = std::abs(cross(a1 - a0, b1 - b0)) / (distance(a0, a1) * distance(b0, b1));
      if (t && turn > 1e-9) shrunk[i] = a0 + *t * (a1 - a0);
      else shrunk[i] = p[i] + std::max(offset[prev], offset[i]) * normal[i];  // collinear edges
    }
    // Too large an aperture turns edges around (or the whole block inside out).
    bool inverted = signed_area(shrunk) <= 0.0 || find_self_intersection(shrunk).has_value();
    for (std::size_t i = 0; i < n && !inverted; ++i)
      inverted = dot(shrunk[(i + 1) % n] - shrunk[i], p[(i + 1) % n] - p[i]) <= 0.0;
    if (inverted)
      throw std::runtime_error("block " + std::to_string(b + 1) + " is too small for an initial aperture of " +
                               std::to_string(aperture) + " m");
    out.push_back(std::move(shrunk));
  }
  return out;
}

}  // namespace hydrodda::geometry
