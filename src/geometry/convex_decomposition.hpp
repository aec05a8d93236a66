#pragma once
// A simple polygon cut into convex pieces along diagonals between its vertices.

#include <span>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::geometry {

// Convex pieces of a simple counter-clockwise polygon, each as the polygon's vertex indices in
// counter-clockwise order; two pieces meet along a diagonal (both its ends vertices of the
// polygon), run one way in one and the other way in the other. Hertel & Mehlhorn (1983), "Fast
// triangulation of simple polygons", FCT'83, LNCS 158: triangulate, then remove each diagonal
// whose two pieces together stay convex; at most four times the fewest convex pieces.
//   triangles = ear clipping: while more than 3 vertices remain, cut off the first ear
//     (a convex corner whose triangle holds no other remaining vertex, boundary included)
//   for each diagonal, in the order made: if piece(left) ∪ piece(right) is convex, merge them
// A corner as straight as 1e-12 of its edges' lengths counts as convex. Throws
// std::invalid_argument for a polygon that is not counter-clockwise or has no ear left
// (a self-intersecting or degenerate one).
std::vector<std::vector<int>> convex_pieces(std::span<const Point> polygon);

}  // namespace hydrodda::geometry
