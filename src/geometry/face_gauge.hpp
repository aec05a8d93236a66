#pragma once
// Gauges across the fracture faces of a block network: at a point of a face, the material
// points of the two blocks' edges that lie on it, followed as the blocks move. The opening is
// their separation along the two edges' mean normal, the shear along it. A block moves
// affinely (DDA's first-order displacement field, rotation applied exactly), so its edges stay
// straight and the opening is linear along a face between gauges. Edges turned θ apart leave
// the opening ambiguous by a factor cos(θ/2) and the shear by the gap × sin(θ/2).

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "geometry/block_network.hpp"
#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

// A material point of a block's edge: vertex `edge` → `edge` + 1, at t along it from the first.
struct EdgePoint {
  int block = -1, edge = -1;
  double t = 0.0;
};

// The two sides of a face at one point: `minus` on the right of the face's direction
// (from → to), `plus` on its left.
struct FaceGauge {
  EdgePoint minus, plus;
};

struct GaugeReading {
  double opening = 0.0;  // m, along the mean normal from minus to plus (< 0: overlap)
  double shear = 0.0;    // m, change of the relative position along the edges since `initial`
  Point midpoint;        // halfway between the two material points
};

class FaceGaugeFinder {
 public:
  // Indexes the network's block edges by the fracture they lie on (keeps a reference).
  explicit FaceGaugeFinder(const BlockNetwork& network);

  // The gauge at point p of `face` (p on its segment), from the nearest edge of the face's
  // fracture on each side; none when a side has no edge of that fracture.
  std::optional<FaceGauge> find(const FractureFace& face, Point p) const;

 private:
  const BlockNetwork& network_;
  std::vector<std::vector<std::pair<int, int>>> edges_;  // per fracture: (block, edge)
};

// The point of `blocks` (current or initial vertices, the network's block and vertex order).
Point material_point(const EdgePoint& point, std::span<const Polygon> blocks);

// The gauge read on the blocks as they are now; `initial` gives the shear's reference.
GaugeReading read_gauge(const FaceGauge& gauge, std::span<const Polygon> now, std::span<const Polygon> initial);

}  // namespace hydrodda::geometry
