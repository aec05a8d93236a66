#pragma once
// Area of the part of a triangle covered by a polygon: the kernel of the equivalent-porosity
// mapping (the paper's §3.2), called once per (fluid element, overlapping block) pair.

#include <array>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

// Area of triangle ∩ polygon. The triangle may be given in either orientation; the polygon is
// simple (convex or not), in either orientation.
//
// Sutherland–Hodgman (1974) with the triangle as the clip region: the polygon is clipped in
// turn by the three half-planes of the (convex) triangle. Against a convex clip region the
// output of a non-convex subject may carry zero-width bridges, but its shoelace area is the
// exact intersection area, which is all that is needed here.
//   for each triangle edge (a, b):
//     out = []
//     for each subject edge (p, q):  keep p if inside; add the crossing if p, q straddle ab
// Hand-written: the library clippers (Boost.Geometry, Clipper, GEOS) are 30–300× slower on
// this triangle-against-block case (DESIGN.md §5), and the coupling loop runs it for every
// element at every pass. Boost.Geometry is the test oracle.
double clipped_area(const std::array<Point, 3>& triangle, std::span<const Point> polygon);

// Area and centroid of triangle ∩ polygon, by the same clip (the area is clipped_area's, bit
// for bit; the centroid of an empty part is meaningless). The seepage force of the coupling
// integrates over these parts of each block.
struct ClippedPart {
  double area = 0.0;
  Point centroid;
};
ClippedPart clip_part(const std::array<Point, 3>& triangle, std::span<const Point> polygon);

// The inside of one edge of a convex polygon: the points p with dot(normal, p − point) >= 0
// (normal: the edge turned to the polygon's inside, not normalised).
struct HalfPlane {
  Point point;
  Point normal;
  double distance(Point p) const { return normal.x * (p.x - point.x) + normal.y * (p.y - point.y); }
};

// The half-planes of a polygon's edges (either orientation), appended to `out`; false, with
// nothing appended, when the polygon is not convex (a turn against its orientation; collinear
// vertices are allowed) or has fewer than three vertices.
bool append_half_planes(std::span<const Point> polygon, std::vector<HalfPlane>& out);

// Area of triangle ∩ the convex region inside every half-plane of `edges`, or `triangle_area`
// itself, the triangle's area as the caller computed it, when no edge cuts the triangle (so a
// triangle wholly inside counts exactly as covered). Sutherland–Hodgman with the region as the
// clip polygon and the triangle as the subject, with early outs:
//   subject = triangle
//   for each edge: d_i = signed distances of the subject's vertices
//                  all d_i >= 0: next edge;  all d_i < 0: return 0
//                  else keep the vertices with d >= 0 and the crossings of the edges that change side
//   return the shoelace area of the subject
// At most kMaxConvexEdges edges (the subject then has at most 3 + kMaxConvexEdges vertices).
inline constexpr int kMaxConvexEdges = 29;
double clipped_area(const std::array<Point, 3>& triangle, double triangle_area, std::span<const HalfPlane> edges);
// The same part's area (bit for bit) and centroid; a triangle wholly inside has its own centroid.
ClippedPart clip_part(const std::array<Point, 3>& triangle, double triangle_area, std::span<const HalfPlane> edges);

// Whether every vertex of the triangle lies inside every half-plane (for a convex region: the
// triangle lies in it, edges included).
bool contains_triangle(std::span<const HalfPlane> edges, const std::array<Point, 3>& triangle);

// Polygons prepared for clipping many triangles against them, as one coupling pass does with
// its blocks: the convex ones (of at most kMaxConvexEdges edges) as their half-planes, the
// others kept for the general clip above. Keeps a view of `polygons`, which must outlive it.
class ClipPolygons {
 public:
  explicit ClipPolygons(std::span<const Polygon> polygons);

  int size() const { return static_cast<int>(boxes_.size()); }
  std::span<const Box> boxes() const { return boxes_; }
  // Area of triangle ∩ polygon i; exactly `triangle_area` when the triangle lies wholly inside
  // a convex polygon i.
  double covered_area(int i, const std::array<Point, 3>& triangle, double triangle_area) const;
  // The same area (bit for bit) with the part's centroid.
  ClippedPart covered_part(int i, const std::array<Point, 3>& triangle, double triangle_area) const;
  // Whether polygon i is convex and holds the whole triangle; false for a non-convex polygon,
  // which covered_area then decides.
  bool holds(int i, const std::array<Point, 3>& triangle) const;

 private:
  std::span<const HalfPlane> edges_of(int i) const {
    return {edges_.data() + first_edge_[i], edges_.data() + first_edge_[i + 1]};
  }

  std::span<const Polygon> polygons_;
  std::vector<Box> boxes_;
  std::vector<int> first_edge_;  // polygon i's half-planes: edges_[first_edge_[i] .. first_edge_[i + 1])
  std::vector<HalfPlane> edges_;  // none for a polygon that is not convex
};

}  // namespace hydrodda::geometry
