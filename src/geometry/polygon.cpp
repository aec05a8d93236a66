#include "geometry/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/spatial_grid.hpp"

namespace hydrodda::geometry {

double signed_area(std::span<const Point> polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return 0.0;
  // Shift to the first vertex: the shoelace sum then loses no digits far from the origin.
  const Point o = polygon[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) twice += cross(polygon[i] - o, polygon[i + 1] - o);
  return 0.5 * twice;
}

double area(std::span<const Point> polygon) { return std::abs(signed_area(polygon)); }

bool turns_left_or_straight(Point a, Point b, Point c) {
  return orient(a, b, c) >= -1e-12 * distance(a, b) * distance(b, c);
}

Point centroid(std::span<const Point> polygon) {
  const std::size_t n = polygon.size();
  if (n == 0) return {};
  const Point o = polygon[0];
  double twice_area = 0.0;
  Point moment{};
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Point a = polygon[i] - o;
    const Point b = polygon[i + 1] - o;
    const double w = cross(a, b);  // twice the area of the fan triangle (o, a, b)
    twice_area += w;
    moment += w * (a + b);         // fan triangle centroid (0 + a + b)/3, weighted
  }
  if (twice_area == 0.0) {
    Point mean{};
    for (Point p : polygon) mean += p;
    return mean / static_cast<double>(n);
  }
  return o + moment / (3.0 * twice_area);
}

Box bounding_box(std::span<const Point> polygon) {
  Box box;
  for (Point p : polygon) box.add(p);
  return box;
}

double width_across_edges(std::span<const Point> polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return 0.0;
  double width = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = polygon[i];
    const Point b = polygon[(i + 1) % n];
    const double length = distance(a, b);
    if (length == 0.0) continue;
    double lo = 0.0, hi = 0.0;
    for (Point p : polygon) {
      const double d = orient(a, b, p) / length;
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    width = std::min(width, hi - lo);
  }
  return std::isfinite(width) ? width : 0.0;
}

namespace {
bool on_segment(Point a, Point b, Point p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
int sign(double v) { return (v > 0.0) - (v < 0.0); }
}  // namespace

bool segments_intersect(Point a, Point b, Point c, Point d) {
  // Segments whose boxes are apart cannot meet, whatever the round-off in the orientations of
  // nearly collinear ones says.
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
    return false;
  const int d1 = sign(orient(c, d, a));
  const int d2 = sign(orient(c, d, b));
  const int d3 = sign(orient(a, b, c));
  const int d4 = sign(orient(a, b, d));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  if (d1 == 0 && on_segment(c, d, a)) return true;
  if (d2 == 0 && on_segment(c, d, b)) return true;
  if (d3 == 0 && on_segment(a, b, c)) return true;
  if (d4 == 0 && on_segment(a, b, d)) return true;
  return false;
}

std::optional<double> line_intersection_parameter(Point a, Point b, Point c, Point d) {
  const Point r = b - a;
  const Point s = d - c;
  const double denom = cross(r, s);
  if (denom == 0.0) return std::nullopt;
  return cross(c - a, s) / denom;
}

namespace {

// Do edges i < j of the polygon meet where they should not: non-adjacent ones anywhere,
// adjacent ones folded back onto each other (collinear and overlapping beyond the shared vertex)?
bool edges_meet(std::span<const Point> polygon, int i, int j) {
  const int n = static_cast<int>(polygon.size());
  const Point a = polygon[i], b = polygon[(i + 1) % n];
  const Point c = polygon[j], d = polygon[(j + 1) % n];
  if ((j == i + 1) || (i == 0 && j == n - 1)) {
    const Point shared = (j == i + 1) ? b : a;
    const Point other_i = (j == i + 1) ? a : b;
    const Point other_j = (j == i + 1) ? d : c;
    return orient(other_i, shared, other_j) == 0.0 && dot(other_i - shared, other_j - shared) > 0.0;
  }
  return segments_intersect(a, b, c, d);
}

// Past this many edges the pairs to test come from a grid of the edges' boxes.
constexpr int kEdgesTestedPairwise = 32;

}  // namespace

std::optional<std::pair<int, int>> find_self_intersection(std::span<const Point> polygon) {
  const int n = static_cast<int>(polygon.size());
  if (n <= kEdgesTestedPairwise) {
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (edges_meet(polygon, i, j)) return std::pair{i, j};
    return std::nullopt;
  }
  // Edges that meet have boxes that overlap: the same first pair as testing every pair.
  std::vector<Box> boxes(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    boxes[i].add(polygon[i]);
    boxes[i].add(polygon[(i + 1) % n]);
  }
  const SpatialGrid grid(boxes);
  for (int i = 0; i < n; ++i) {
    int first = n;
    grid.for_each_overlap(boxes[i], [&](int j) {
      if (j > i && j < first && edges_meet(polygon, i, j)) first = j;
    });
    if (first < n) return std::pair{i, first};
  }
  return std::nullopt;
}

bool contains(std::span<const Point> polygon, Point p) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point a = polygon[i];
    const Point b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x_cross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x_cross) inside = !inside;
    }
  }
  return inside;
}

std::vector<std::pair<double, double>> clip_segment_to_polygon(Point a, Point b, std::span<const Point> polygon,
                                                               bool keep_inside) {
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

Point closest_point_on_segment(Point p, Point a, Point b) {
  const Point ab = b - a;
  const double len2 = dot(ab, ab);
  if (len2 == 0.0) return a;
  const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  return a + t * ab;
}

double distance_to_segment(Point p, Point a, Point b) { return distance(p, closest_point_on_segment(p, a, b)); }

}  // namespace hydrodda::geometry
