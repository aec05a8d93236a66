#include "geometry/clipping.hpp"

#include <cmath>

#include "geometry/polygon.hpp"

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

}  // namespace

double clipped_area(const std::array<Point, 3>& triangle, std::span<const Point> polygon) {
  std::array<Point, 3> t = triangle;
  if (orient(t[0], t[1], t[2]) < 0.0) std::swap(t[1], t[2]);
  thread_local VertexBuffer a;
  thread_local VertexBuffer b;
  a.clear();
  for (Point p : polygon) a.push(p);
  clip_by_half_plane(a, t[0], t[1], b);
  clip_by_half_plane(b, t[1], t[2], a);
  clip_by_half_plane(a, t[2], t[0], b);
  return area(b.view());
}

}  // namespace hydrodda::geometry
