#include "geometry/clipping.hpp"

#include <algorithm>
#include <cmath>

namespace hydrodda::geometry {

namespace {

// Small-buffer polygon: a clip of an n-gon by three half-planes has at most n + 3 vertices, and
// blocks rarely have more than a few dozen; larger ones fall back to the heap.
class VertexBuffer {
 public:
  void clear() { size_ = 0; }
  void push(Point p) {
    if (size_ < kInline) inline_[size_] = p;
    else {
      if (heap_.size() < size_ + 1) heap_.resize(size_ + 1);
      if (size_ == kInline) std::copy(inline_.begin(), inline_.end(), heap_.begin());
      heap_[size_] = p;
    }
    ++size_;
  }
  std::size_t size() const { return size_; }
  Point operator[](std::size_t i) const { return size_ <= kInline ? inline_[i] : heap_[i]; }
  std::span<const Point> view() const {
    return size_ <= kInline ? std::span<const Point>(inline_.data(), size_)
                            : std::span<const Point>(heap_.data(), size_);
  }

 private:
  static constexpr std::size_t kInline = 64;
  std::array<Point, kInline> inline_{};
  std::vector<Point> heap_;
  std::size_t size_ = 0;
};

// Keeps the part of `in` on the left of the directed line a→b (orient(a, b, p) >= 0).
void clip_by_half_plane(const VertexBuffer& in, Point a, Point b, VertexBuffer& out) {
  out.clear();
  const std::size_t n = in.size();
  if (n == 0) return;
  const Point ab = b - a;
  Point p = in[n - 1];
  double sp = cross(ab, p - a);
  for (std::size_t i = 0; i < n; ++i) {
    const Point q = in[i];
    const double sq = cross(ab, q - a);
    if (sq >= 0.0) {
      if (sp < 0.0) out.push(p + (sp / (sp - sq)) * (q - p));
      out.push(q);
    } else if (sp >= 0.0) {
      out.push(p + (sp / (sp - sq)) * (q - p));
    }
    p = q;
    sp = sq;
  }
}

// triangle ∩ polygon as a polygon (in the polygon's orientation), in a buffer of this thread.
std::span<const Point> clip(const std::array<Point, 3>& triangle, std::span<const Point> polygon) {
  std::array<Point, 3> t = triangle;
  if (orient(t[0], t[1], t[2]) < 0.0) std::swap(t[1], t[2]);
  thread_local VertexBuffer a;
  thread_local VertexBuffer b;
  a.clear();
  for (Point p : polygon) a.push(p);
  clip_by_half_plane(a, t[0], t[1], b);
  clip_by_half_plane(b, t[1], t[2], a);
  clip_by_half_plane(a, t[2], t[0], b);
  return b.view();
}
}  // namespace

double clipped_area(const std::array<Point, 3>& triangle, std::span<const Point> polygon) {
  return area(clip(triangle, polygon));
}

ClippedPart clip_part(const std::array<Point, 3>& triangle, std::span<const Point> polygon) {
  const std::span<const Point> part = clip(triangle, polygon);
  return {area(part), centroid(part)};
}

namespace {

// Sutherland–Hodgman with the convex region as the clip polygon, the triangle as the subject;
// the centroid only when asked (the area is the same either way, bit for bit).
template <bool kCentroid>
ClippedPart clip_by_half_planes(const std::array<Point, 3>& triangle, std::span<const HalfPlane> edges) {
  constexpr int kCapacity = 3 + kMaxConvexEdges;
  std::array<Point, kCapacity> first, second;
  std::array<double, kCapacity> d;
  Point* in = first.data();
  Point* out = second.data();
  std::copy(triangle.begin(), triangle.end(), in);
  int n = 3;
  for (const HalfPlane& edge : edges) {
    bool all_in = true, all_out = true;
    for (int i = 0; i < n; ++i) {
      d[i] = edge.distance(in[i]);
      all_in &= d[i] >= 0.0;
      all_out &= d[i] < 0.0;
    }
    if (all_in) continue;
    if (all_out) return {};
    int kept = 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {  // the subject's edge in[j] → in[i]
      if ((d[j] >= 0.0) != (d[i] >= 0.0)) out[kept++] = in[j] + (d[j] / (d[j] - d[i])) * (in[i] - in[j]);
      if (d[i] >= 0.0) out[kept++] = in[i];
    }
    n = kept;
    std::swap(in, out);
  }
  const std::span<const Point> part(in, n);
  if constexpr (kCentroid) return {area(part), centroid(part)};
  return {area(part), {}};
}

Point triangle_centroid(const std::array<Point, 3>& t) { return (1.0 / 3.0) * (t[0] + t[1] + t[2]); }

// The convex clip of clipped_area below, with the part's centroid when kCentroid.
template <bool kCentroid>
ClippedPart clip_convex(const std::array<Point, 3>& triangle, double triangle_area, std::span<const HalfPlane> edges) {
  // Which edges cut the triangle: the common case in a fractured layer is one (the element
  // crosses a single fracture face), whose answer is closed-form; more go through the clip.
  int cutting = 0;
  std::array<double, 3> d{};
  for (const HalfPlane& edge : edges) {
    const std::array<double, 3> e{edge.distance(triangle[0]), edge.distance(triangle[1]), edge.distance(triangle[2])};
    const int outside = (e[0] < 0.0) + (e[1] < 0.0) + (e[2] < 0.0);
    if (outside == 3) return {};
    if (outside == 0) continue;
    if (++cutting > 1) return clip_by_half_planes<kCentroid>(triangle, edges);
    d = e;
  }
  if (cutting == 0) {
    if constexpr (kCentroid) return {triangle_area, triangle_centroid(triangle)};
    return {triangle_area, {}};
  }
  // One line cuts: corner k alone on its side, at distances d_k and d_i, d_j from the line,
  // cuts its two edges at fractions t = d_k / (d_k − d_i) from it, a corner triangle of
  // t_i t_j of the whole (similar triangles). That corner is the part outside when k is the
  // one corner outside, the part inside when k is the one corner inside.
  const bool one_outside = (d[0] < 0.0) + (d[1] < 0.0) + (d[2] < 0.0) == 1;
  const int k = one_outside ? (d[0] < 0.0 ? 0 : d[1] < 0.0 ? 1 : 2) : (d[0] >= 0.0 ? 0 : d[1] >= 0.0 ? 1 : 2);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double ti = d[k] / (d[k] - d[i]), tj = d[k] / (d[k] - d[j]);
  const double corner = ti * tj;
  const double part_area = one_outside ? triangle_area * (1.0 - corner) : triangle_area * corner;
  if constexpr (!kCentroid) return {part_area, {}};
  // The corner triangle's centroid is the mean of its corners; the rest's, by first moments:
  // A c_T = A_corner c_corner + A_rest c_rest.
  const Point pk = triangle[k];
  const Point corner_centroid =
      (1.0 / 3.0) * (pk + (pk + ti * (triangle[i] - pk)) + (pk + tj * (triangle[j] - pk)));
  if (!one_outside) return {part_area, corner_centroid};
  const double corner_area = triangle_area * corner;
  return {part_area, (1.0 / part_area) * (triangle_area * triangle_centroid(triangle) - corner_area * corner_centroid)};
}

}  // namespace

bool append_half_planes(std::span<const Point> polygon, std::vector<HalfPlane>& out) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  const double orientation = signed_area(polygon);
  if (orientation == 0.0) return false;
  const double sign = orientation > 0.0 ? 1.0 : -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point before = polygon[(i + n - 1) % n], at = polygon[i], after = polygon[(i + 1) % n];
    if (sign * cross(at - before, after - at) < 0.0) return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = polygon[i], b = polygon[(i + 1) % n];
    // The edge a→b turned a quarter towards the inside: to its left when counter-clockwise.
    out.push_back({a, {-sign * (b.y - a.y), sign * (b.x - a.x)}});
  }
  return true;
}

double clipped_area(const std::array<Point, 3>& triangle, double triangle_area, std::span<const HalfPlane> edges) {
  return clip_convex<false>(triangle, triangle_area, edges).area;
}

ClippedPart clip_part(const std::array<Point, 3>& triangle, double triangle_area, std::span<const HalfPlane> edges) {
  return clip_convex<true>(triangle, triangle_area, edges);
}

bool contains_triangle(std::span<const HalfPlane> edges, const std::array<Point, 3>& triangle) {
  for (const HalfPlane& edge : edges)
    if (edge.distance(triangle[0]) < 0.0 || edge.distance(triangle[1]) < 0.0 || edge.distance(triangle[2]) < 0.0)
      return false;
  return true;
}

ClipPolygons::ClipPolygons(std::span<const Polygon> polygons) : polygons_(polygons) {
  boxes_.reserve(polygons.size());
  first_edge_.reserve(polygons.size() + 1);
  first_edge_.push_back(0);
  for (const Polygon& p : polygons) {
    boxes_.push_back(bounding_box(p));
    if (p.size() <= static_cast<std::size_t>(kMaxConvexEdges)) append_half_planes(p, edges_);
    first_edge_.push_back(static_cast<int>(edges_.size()));
  }
}

double ClipPolygons::covered_area(int i, const std::array<Point, 3>& triangle, double triangle_area) const {
  const std::span<const HalfPlane> edges = edges_of(i);
  return edges.empty() ? clipped_area(triangle, polygons_[i]) : clipped_area(triangle, triangle_area, edges);
}

ClippedPart ClipPolygons::covered_part(int i, const std::array<Point, 3>& triangle, double triangle_area) const {
  const std::span<const HalfPlane> edges = edges_of(i);
  return edges.empty() ? clip_part(triangle, polygons_[i]) : clip_part(triangle, triangle_area, edges);
}

bool ClipPolygons::holds(int i, const std::array<Point, 3>& triangle) const {
  const std::span<const HalfPlane> edges = edges_of(i);
  return !edges.empty() && contains_triangle(edges, triangle);
}

}  // namespace hydrodda::geometry
