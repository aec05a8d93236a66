#include "geometry/face_gauge.hpp"

#include <limits>

namespace hydrodda::geometry {

namespace {

Point normalised(Point p) { return p / norm(p); }

// Outward unit normal of a counter-clockwise polygon's edge: its right.
Point outward_normal(const EdgePoint& r, std::span<const Polygon> blocks) {
  const Polygon& poly = blocks[r.block];
  const Point along = poly[(r.edge + 1) % poly.size()] - poly[r.edge];
  return normalised(Point{along.y, -along.x});
}

}  // namespace

FaceGaugeFinder::FaceGaugeFinder(const BlockNetwork& network) : network_(network) {
  int fractures = 0;
  for (const std::vector<int>& edge_fractures : network.edge_fractures)
    for (int f : edge_fractures) fractures = std::max(fractures, f + 1);
  for (const FractureFace& face : network.faces) fractures = std::max(fractures, face.fracture + 1);
  edges_.resize(static_cast<std::size_t>(fractures));
  for (std::size_t b = 0; b < network.blocks.size(); ++b)
    for (std::size_t e = 0; e < network.edge_fractures[b].size(); ++e)
      if (const int f = network.edge_fractures[b][e]; f >= 0)
        edges_[f].push_back({static_cast<int>(b), static_cast<int>(e)});
}

std::optional<FaceGauge> FaceGaugeFinder::find(const FractureFace& face, Point p) const {
  const Point d = face.segment.to - face.segment.from;
  if (!(norm(d) > 0.0)) return std::nullopt;
  const Point n = normalised(Point{-d.y, d.x});  // the face's left
  // The nearest edge of the fracture on one side: a block on the +n side has its outward
  // normal along −n there. At a face's end, where the fracture crosses another, the edges of
  // the next face along it end at p too; of edges equally near (within round-off of the
  // face's length) the face's own, the one nearest its middle, is taken, or the gauge there
  // would read the blocks beyond the junction.
  const Point middle = (face.segment.from + face.segment.to) * 0.5;
  const double tie = 1e-9 * norm(d);
  const auto side_at = [&](double side) {
    EdgePoint best;
    double best_distance = std::numeric_limits<double>::infinity();
    double best_to_middle = std::numeric_limits<double>::infinity();
    for (const auto& [b, e] : edges_[face.fracture]) {
      const Polygon& poly = network_.blocks[b];
      const Point a = poly[e], c = poly[(e + 1) % poly.size()];
      const Point along = c - a;
      const double edge_length = norm(along);
      if (!(edge_length > 0.0)) continue;
      const Point outward{along.y / edge_length, -along.x / edge_length};
      if (side * dot(outward, n) > -0.5) continue;
      const double distance = distance_to_segment(p, a, c);
      if (distance > best_distance + tie) continue;
      const double to_middle = distance_to_segment(middle, a, c);
      if (distance < best_distance - tie || to_middle < best_to_middle) {
        best_distance = std::min(best_distance, distance);
        best_to_middle = to_middle;
        best = {b, e, dot(p - a, along) / (edge_length * edge_length)};
      }
    }
    return best;
  };
  FaceGauge gauge{side_at(-1.0), side_at(+1.0)};
  if (gauge.minus.block < 0 || gauge.plus.block < 0) return std::nullopt;
  return gauge;
}

Point material_point(const EdgePoint& r, std::span<const Polygon> blocks) {
  const Polygon& poly = blocks[r.block];
  const Point a = poly[r.edge], c = poly[(r.edge + 1) % poly.size()];
  return a + (c - a) * r.t;
}

GaugeReading read_gauge(const FaceGauge& gauge, std::span<const Polygon> now, std::span<const Polygon> initial) {
  const Point minus = material_point(gauge.minus, now), plus = material_point(gauge.plus, now);
  // The frame of the two edges as they are now: their mean normal, from minus to plus.
  const Point normal = normalised(outward_normal(gauge.minus, now) - outward_normal(gauge.plus, now));
  const Point tangent{-normal.y, normal.x};
  const Point gap = plus - minus;
  const Point initial_gap = material_point(gauge.plus, initial) - material_point(gauge.minus, initial);
  return {dot(gap, normal), dot(gap - initial_gap, tangent), (plus + minus) * 0.5};
}

}  // namespace hydrodda::geometry
