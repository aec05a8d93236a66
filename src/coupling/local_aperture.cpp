#include "coupling/local_aperture.hpp"

#include <algorithm>
#include <limits>

#include "geometry/spatial_grid.hpp"

namespace hydrodda::coupling {

using geometry::Point;

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
  for (std::size_t e = 0; e < centroids.size(); ++e) {
    if (fracture_area[e] <= 0.0) continue;
    const Point c = centroids[e];
    // The two nearest walls within reach; a missing wall is taken at `reach`.
    double first = reach, second = reach;
    int walls = 0;
    const auto consider = [&](double s) {
      if (s >= reach) return;
      ++walls;
      if (s < first) {
        second = first;
        first = s;
      } else if (s < second) {
        second = s;
      }
    };
    grid.for_each_overlap(geometry::Box{c, c}.inflated(reach), [&](int b) { consider(signed_distance(c, blocks[b])); });
    // The domain boundary is the second wall only where no second block is within reach: a
    // fracture meeting the boundary is bounded by its two blocks, not by the boundary.
    if (walls < 2 && !domain.empty()) consider(-signed_distance(c, domain));  // inside: positive
    aperture[e] = std::max(0.0, first + second);
  }
  return aperture;
}

}  // namespace hydrodda::coupling
