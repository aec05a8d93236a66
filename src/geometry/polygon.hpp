#pragma once
// Simple polygons as vertex lists (no repeated closing vertex) and the measures on them.

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::geometry {

using Polygon = std::vector<Point>;

// A straight segment, e.g. a fracture trace.
struct Segment2 {
  Point from;
  Point to;
};

// Shoelace formula: A = ½ Σ (x_i y_{i+1} − x_{i+1} y_i); > 0 for counter-clockwise.
double signed_area(std::span<const Point> polygon);
double area(std::span<const Point> polygon);
// Area centroid: c = 1/(6A) Σ (p_i + p_{i+1}) (x_i y_{i+1} − x_{i+1} y_i).
Point centroid(std::span<const Point> polygon);
Box bounding_box(std::span<const Point> polygon);
// Whether the turn a → b → c is not against the counter-clockwise orientation, a straight one
// (within 1e-12 of its edges' lengths) included.
bool turns_left_or_straight(Point a, Point b, Point c);
// The polygon's width across its edges: the smallest, over its edges, of its extent along the
// edge's normal (max − min of the vertices' distances from the edge's line). For a convex
// polygon the width between the closest pair of parallel supporting lines (one of them always
// lies along an edge; Toussaint's rotating calipers); 0 for fewer than three vertices.
double width_across_edges(std::span<const Point> polygon);

// Do closed segments ab and cd share a point (touching and collinear overlap included)?
bool segments_intersect(Point a, Point b, Point c, Point d);
// The intersection point of the lines through ab and cd, parameterised along ab
// (a + t (b − a)); empty when the lines are parallel.
std::optional<double> line_intersection_parameter(Point a, Point b, Point c, Point d);

// First pair of non-adjacent edges that intersect (or adjacent ones folded back onto each
// other), as edge indices (i, j), i < j, the first i then the first j; the edge i runs from
// vertex i to vertex i+1. Past a few dozen edges only the pairs whose boxes overlap are tested
// (a grid of the edges' boxes): time near-linear in n for a polygon whose edges are short.
std::optional<std::pair<int, int>> find_self_intersection(std::span<const Point> polygon);

// Point in polygon by the crossing-number rule; points on the boundary may go either way.
bool contains(std::span<const Point> polygon, Point p);

// The parts of segment ab inside the polygon (or outside it, keep_inside = false), as
// parameter intervals [t0, t1] along ab (a + t (b − a)), in order: ab is cut where it crosses
// the polygon's edges and each piece is kept or not by its midpoint.
std::vector<std::pair<double, double>> clip_segment_to_polygon(Point a, Point b, std::span<const Point> polygon,
                                                               bool keep_inside = true);

// Distance from p to the closed segment ab.
double distance_to_segment(Point p, Point a, Point b);
// The point of segment ab nearest to p (a when the segment has no length).
Point closest_point_on_segment(Point p, Point a, Point b);

}  // namespace hydrodda::geometry
