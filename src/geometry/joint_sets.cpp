#include "geometry/joint_sets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geometry/portable_random.hpp"

namespace hydrodda::geometry {

namespace {

// The unit direction of a line at `degrees`, exact for lines along the axes (cos 90° in
// floating point is 6e-17, which would tip a vertical set's normal).
Point direction_of(double degrees) {
  double a = std::fmod(degrees, 180.0);
  if (a < 0.0) a += 180.0;
  if (a == 0.0) return {1.0, 0.0};
  if (a == 90.0) return {0.0, 1.0};
  const double r = a * std::numbers::pi / 180.0;
  return {std::cos(r), std::sin(r)};
}

// A normal draw around `mean`, drawn again while below a tenth of the mean (lengths and
// spacings are positive); after 100 tries, a tenth of the mean.
double draw_positive(PortableRandom& random, double mean, double spread) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const double value = mean + spread * random.normal();
    if (value >= 0.1 * mean) return value;
  }
  return 0.1 * mean;
}

}  // namespace

Point joint_set_normal(double angle_degrees) {
  const Point d = direction_of(angle_degrees);  // d.y ≥ 0: the angle lies in [0°, 180°)
  const Point n{-d.y, d.x};
  return (n.y > 0.0 || (n.y == 0.0 && n.x > 0.0)) ? n : Point{-n.x, -n.y};
}

Point find_lowest_corner(const Polygon& region, double angle_degrees) {
  const Point n = joint_set_normal(angle_degrees);
  const Point d = direction_of(angle_degrees);
  Point best = region.front();
  for (Point p : region) {
    const double a = dot(n, p), b = dot(n, best);
    if (a < b || (a == b && dot(d, p) < dot(d, best))) best = p;
  }
  return best;
}

std::vector<Segment2> generate_joint_traces(const JointSet& set, std::size_t max_traces) {
  if (set.region.size() < 3) throw std::invalid_argument("joint set: the region needs at least 3 vertices");
  if (!(set.spacing > 0.0)) throw std::invalid_argument("joint set: spacing must be > 0");
  const Point n = joint_set_normal(set.angle);
  const Point d = direction_of(set.angle);
  const Point corner = find_lowest_corner(set.region, set.angle);
  const Point middle = centroid(set.region);
  double extent = 0.0;
  for (Point p : set.region) extent = std::max(extent, dot(n, p - corner));

  PortableRandom random(set.seed);
  std::vector<Segment2> traces;
  const auto add_inside = [&](Point a, Point b) {
    for (auto [t0, t1] : clip_segment_to_polygon(a, b, set.region)) {
      if (traces.size() == max_traces)
        throw std::invalid_argument("joint set: more than " + std::to_string(max_traces) + " traces");
      traces.push_back({a + t0 * (b - a), a + t1 * (b - a)});
    }
  };
  for (double s = set.offset.value_or(0.5 * set.spacing); s <= extent;
       s += draw_positive(random, set.spacing, set.spacing_spread)) {
    const double degrees = set.angle + set.angle_spread * random.normal();
    const Point dk = set.angle_spread > 0.0 ? direction_of(degrees) : d;
    const Point pivot = corner + s * n + dot(d, middle - corner) * d;
    // The line's reach across the region: the region's projection on it.
    double lo = INFINITY, hi = -INFINITY;
    for (Point p : set.region) {
      lo = std::min(lo, dot(dk, p - pivot));
      hi = std::max(hi, dot(dk, p - pivot));
    }
    if (!set.length) {
      add_inside(pivot + lo * dk, pivot + hi * dk);
      continue;
    }
    const double gap = set.gap.value_or(*set.length);
    double u = lo - random.uniform() * (*set.length + gap);
    while (u < hi) {
      const double length = draw_positive(random, *set.length, set.length_spread);
      add_inside(pivot + u * dk, pivot + (u + length) * dk);
      u += length + draw_positive(random, gap, set.gap_spread);
    }
  }
  return traces;
}

}  // namespace hydrodda::geometry
