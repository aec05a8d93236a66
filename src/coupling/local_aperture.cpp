#include "coupling/local_aperture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "geometry/spatial_grid.hpp"

namespace hydrodda::coupling {

using geometry::Point;

namespace {

// A wall seen from a centroid: its signed distance s (negative inside the solid) and the unit
// direction in which s grows, from the wall's nearest point (none when the centroid lies on
// the wall).
struct Wall {
  double s = 0.0;
  std::optional<Point> rising;
};

// `solid_inside`: the solid is the polygon's inside (a block) or its outside (the domain).
Wall make_wall(Point c, std::span<const Point> polygon, bool solid_inside) {
  double d = std::numeric_limits<double>::infinity();
  Point nearest = c;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point q = geometry::closest_point_on_segment(c, polygon[i], polygon[(i + 1) % polygon.size()]);
    const double dq = geometry::distance(c, q);
    if (dq < d) {
      d = dq;
      nearest = q;
    }
  }
  const bool in_solid = geometry::contains(polygon, c) == solid_inside;
  Wall wall{in_solid ? -d : d, std::nullopt};
  if (d > 0.0) wall.rising = (in_solid ? nearest - c : c - nearest) / d;
  return wall;
}

// Two walls bound one gap through the centroid when their distances grow in opposite
// directions (within 45°: fracture walls need not be parallel).
bool facing(const Wall& a, const Wall& b) {
  if (!a.rising || !b.rising) return true;
  return geometry::dot(*a.rising, *b.rising) <= -std::sqrt(0.5);
}

}  // namespace

double signed_distance(Point p, std::span<const Point> polygon) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i)
    d = std::min(d, geometry::distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  return geometry::contains(polygon, p) ? -d : d;
}

std::vector<double> compute_local_apertures(std::span<const Point> centroids, std::span<const double> fracture_area,
                                            std::span<const geometry::Polygon> blocks,
                                            const geometry::Polygon& domain, double reach) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(blocks.size());
  for (const auto& b : blocks) boxes.push_back(geometry::bounding_box(b));
  const geometry::SpatialGrid grid(boxes, 1.0);
  std::vector<double> aperture(centroids.size(), 0.0);
  std::vector<Wall> walls;
  for (std::size_t e = 0; e < centroids.size(); ++e) {
    if (fracture_area[e] <= 0.0) continue;
    const Point c = centroids[e];
    // The block walls within reach, nearest first.
    walls.clear();
    grid.for_each_overlap(geometry::Box{c, c}.inflated(reach), [&](int b) {
      const Wall w = make_wall(c, blocks[b], true);
      if (w.s < reach) walls.push_back(w);
    });
    std::sort(walls.begin(), walls.end(), [](const Wall& a, const Wall& b) { return a.s < b.s; });
    const std::size_t block_walls = walls.size();
    std::optional<Wall> boundary;
    if (!domain.empty()) {
      const Wall w = make_wall(c, domain, false);
      if (w.s < reach) boundary = w;
    }
    // The two nearest walls, a missing one taken at `reach`. The domain boundary is the second
    // wall only where no second block is within reach: a fracture meeting the boundary is
    // bounded by its two blocks, not by the boundary.
    std::vector<Wall> nearest(walls.begin(), walls.begin() + std::min<std::size_t>(2, block_walls));
    if (block_walls < 2 && boundary) {
      nearest.push_back(*boundary);
      std::sort(nearest.begin(), nearest.end(), [](const Wall& a, const Wall& b) { return a.s < b.s; });
    }
    const double first = nearest.size() > 0 ? nearest[0].s : reach;
    const double second = nearest.size() > 1 ? nearest[1].s : reach;
    double width = first + second;
    // Two nearest walls that do not face each other bound no gap together: a centroid inside a
    // block that has come off the domain boundary is nearest to that block's face along the
    // boundary, and the next block (across a fracture) lies to one side, not across. The gap
    // is then the one between facing walls, the domain boundary included (the sliver the block
    // left); with none such, the sum of the two nearest stands.
    if (nearest.size() == 2 && !facing(nearest[0], nearest[1])) {
      if (boundary) walls.push_back(*boundary);
      double narrowest = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < walls.size(); ++i)
        for (std::size_t j = i + 1; j < walls.size(); ++j) {
          const double sum = walls[i].s + walls[j].s;
          if (sum > 0.0 && sum < narrowest && facing(walls[i], walls[j])) narrowest = sum;
        }
      if (std::isfinite(narrowest)) width = narrowest;
    }
    aperture[e] = std::max(0.0, width);
  }
  return aperture;
}

}  // namespace hydrodda::coupling
