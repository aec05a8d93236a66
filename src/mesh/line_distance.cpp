#include "mesh/line_distance.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/polygon.hpp"

namespace hydrodda::mesh {

namespace {

using geometry::Box;
using geometry::Point;

// Each segment cut into pieces no longer than 2 × reach, the boxes of the pieces and, for each
// piece, the segment it is part of: a long oblique trace's own box would cover half the
// domain and be visited by every query.
struct Pieces {
  std::vector<Box> boxes;
  std::vector<int> line;
};

Pieces cut_into_pieces(std::span<const Segment> lines, double reach) {
  Pieces out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Point a = lines[i].from, b = lines[i].to;
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int count = std::clamp(static_cast<int>(std::ceil(length / (2.0 * reach))), 1, 1 << 20);
    for (int k = 0; k < count; ++k) {
      const double t0 = static_cast<double>(k) / count, t1 = static_cast<double>(k + 1) / count;
      Box box;
      box.add({a.x + t0 * (b.x - a.x), a.y + t0 * (b.y - a.y)});
      box.add(k + 1 == count ? b : Point{a.x + t1 * (b.x - a.x), a.y + t1 * (b.y - a.y)});
      // Widened by round-off's worth of the segment's size, so that a piece's box holds
      // every point of the segment between its two ends.
      const double slack = 1e-12 * (length + std::abs(a.x) + std::abs(a.y) + std::abs(b.x) + std::abs(b.y));
      out.boxes.push_back(box.inflated(slack));
      out.line.push_back(static_cast<int>(i));
    }
  }
  return out;
}

}  // namespace

LineDistance::LineDistance(std::span<const Segment> lines, double reach)
    : lines_(lines.begin(), lines.end()), reach_(reach), grid_([&] {
        Pieces pieces = cut_into_pieces(lines, reach);
        line_of_piece_ = std::move(pieces.line);
        return geometry::SpatialGrid(pieces.boxes);
      }()) {}

double LineDistance::nearest(Point p) const {
  // Every point of a segment within the reach of p lies in the query box, so the piece
  // holding it is visited.
  const Box query{{p.x - reach_, p.y - reach_}, {p.x + reach_, p.y + reach_}};
  double d = INFINITY;
  grid_.for_each_overlap(query, [&](int piece) {
    const Segment& s = lines_[line_of_piece_[piece]];
    d = std::min(d, geometry::distance_to_segment(p, s.from, s.to));
  });
  return d;
}

}  // namespace hydrodda::mesh
