#include "coupling/local_aperture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "numerics/parallel.hpp"
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
// The nearest point and the crossing test are geometry::closest_point_on_segment and
// geometry::contains written out with the same arithmetic, for speed: this runs for every
// edge of every block near every open element, each pass. The edges are compared by squared
// distance, with one square root at the end (the same distance: the root is monotone).
Wall make_wall(Point c, std::span<const Point> polygon, bool solid_inside) {
  double d2 = std::numeric_limits<double>::infinity();
  Point nearest = c;
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = polygon[i], b = polygon[i + 1 < n ? i + 1 : 0];  // the edge a → b
    const Point ab = b - a;
    const double len2 = geometry::dot(ab, ab);
    const double along = geometry::dot(c - a, ab);
    // t = clamp(along / len2, 0, 1), divided only where the foot falls inside the edge.
    const Point q = len2 == 0.0 || along <= 0.0 ? a : along >= len2 ? a + ab : a + (along / len2) * ab;
    const Point cq = q - c;
    const double dq2 = cq.x * cq.x + cq.y * cq.y;
    if (dq2 < d2) {
      d2 = dq2;
      nearest = q;
    }
    // The crossing of the ray from c to +x, from b towards a as contains() takes each edge.
    if ((b.y > c.y) != (a.y > c.y)) {
      const double x_cross = b.x + (c.y - b.y) * (a.x - b.x) / (a.y - b.y);
      if (c.x < x_cross) inside = !inside;
    }
  }
  const double d = std::sqrt(d2);
  const bool in_solid = inside == solid_inside;
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

bool nearer(const Wall& a, const Wall& b) { return a.s < b.s; }

// The aperture at one centroid, from the blocks near it (found through `grid`) and the domain.
// `walls`: scratch space, kept from call to call.
double compute_local_aperture(Point c, std::span<const geometry::Polygon> blocks, const geometry::SpatialGrid& grid,
                              const geometry::Polygon& domain, double reach, std::vector<Wall>& walls) {
  // The block walls within reach, nearest first.
  walls.clear();
  grid.for_each_overlap(geometry::Box{c, c}.inflated(reach), [&](int b) {
    const Wall w = make_wall(c, blocks[b], true);
    if (w.s < reach) walls.push_back(w);
  });
  std::sort(walls.begin(), walls.end(), nearer);
  const std::size_t block_walls = walls.size();
  // The domain boundary's wall within reach, found only where it can count.
  std::optional<Wall> boundary;
  bool boundary_sought = false;
  const auto find_boundary = [&]() -> const std::optional<Wall>& {
    if (!boundary_sought && !domain.empty()) {
      const Wall w = make_wall(c, domain, false);
      if (w.s < reach) boundary = w;
    }
    boundary_sought = true;
    return boundary;
  };
  // The two nearest walls, a missing one taken at `reach`. The domain boundary is the second
  // wall only where no second block is within reach: a fracture meeting the boundary is
  // bounded by its two blocks, not by the boundary.
  std::array<Wall, 2> nearest;
  std::size_t count = std::min<std::size_t>(2, block_walls);
  std::copy(walls.begin(), walls.begin() + count, nearest.begin());
  if (block_walls < 2 && find_boundary()) {
    nearest[count++] = *boundary;
    if (count == 2 && nearer(nearest[1], nearest[0])) std::swap(nearest[0], nearest[1]);
  }
  const double first = count > 0 ? nearest[0].s : reach;
  const double second = count > 1 ? nearest[1].s : reach;
  double width = first + second;
  // Two nearest walls that do not face each other bound no gap together: a centroid inside a
  // block that has come off the domain boundary is nearest to that block's face along the
  // boundary, and the next block (across a fracture) lies to one side, not across. The gap
  // is then the one between facing walls, the domain boundary included (the sliver the block
  // left); with none such, the sum of the two nearest stands.
  if (count == 2 && !facing(nearest[0], nearest[1])) {
    if (find_boundary()) walls.push_back(*boundary);
    double narrowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < walls.size(); ++i)
      for (std::size_t j = i + 1; j < walls.size(); ++j) {
        const double sum = walls[i].s + walls[j].s;
        if (sum > 0.0 && sum < narrowest && facing(walls[i], walls[j])) narrowest = sum;
      }
    if (std::isfinite(narrowest)) width = narrowest;
  }
  return std::max(0.0, width);
}

}  // namespace

double signed_distance(Point p, std::span<const Point> polygon) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i)
    d = std::min(d, geometry::distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  return geometry::contains(polygon, p) ? -d : d;
}

namespace {
// compute_local_apertures over `count` elements, `centroid(e)` giving element e's centroid.
template <class Centroid>
std::vector<double> apertures_at(std::size_t count, Centroid&& centroid, std::span<const double> fracture_area,
                                 std::span<const geometry::Polygon> blocks, const geometry::Polygon& domain,
                                 double reach) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(blocks.size());
  for (const auto& b : blocks) boxes.push_back(geometry::bounding_box(b));
  const geometry::SpatialGrid grid(boxes, 1.0);
  std::vector<double> aperture(count, 0.0);
  // Each element on its own: chunks over the threads give the same apertures as one thread.
  numerics::for_each_chunk(count >= 20000, count, 1024, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::vector<Wall> walls;
    for (std::size_t e = begin; e < end; ++e)
      if (fracture_area[e] > 0.0) aperture[e] = compute_local_aperture(centroid(e), blocks, grid, domain, reach, walls);
  });
  return aperture;
}
}  // namespace

std::vector<double> compute_local_apertures(std::span<const Point> centroids, std::span<const double> fracture_area,
                                            std::span<const geometry::Polygon> blocks,
                                            const geometry::Polygon& domain, double reach) {
  return apertures_at(
      centroids.size(), [&](std::size_t e) { return centroids[e]; }, fracture_area, blocks, domain, reach);
}

std::vector<double> compute_local_apertures(const mesh::TriangleMesh& mesh, std::span<const double> fracture_area,
                                            std::span<const geometry::Polygon> blocks,
                                            const geometry::Polygon& domain, double reach) {
  return apertures_at(
      mesh.triangles.size(), [&](std::size_t e) { return mesh::triangle_centroid(mesh, static_cast<int>(e)); },
      fracture_area, blocks, domain, reach);
}

}  // namespace hydrodda::coupling
