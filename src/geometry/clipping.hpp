#pragma once
// Area of the part of a triangle covered by a polygon: the kernel of the equivalent-porosity
// mapping (the paper's §3.2), called once per (fluid element, overlapping block) pair.

#include <array>
#include <span>

#include "geometry/point.hpp"

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

}  // namespace hydrodda::geometry
