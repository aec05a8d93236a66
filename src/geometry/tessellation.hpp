#pragma once
// Intact rock as sub-blocks: a polygon (a block cut from the domain) tessellated into
// Voronoi cells of seeded points, or into triangles (each Voronoi cell fanned from its
// centroid), every face between two sub-blocks named by both, so that each is a bond.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

enum class TessellationKind { voronoi, triangles };

// Seeds on a jittered grid over `box`: one per square of side `size` (whole squares from
// box.lo), uniform in it, drawn in row order from PortableRandom(seed); the same seeds on any
// machine. The cells then have a mean area of size².
std::vector<Point> generate_seeds(const Box& box, double size, std::uint64_t seed);

// The seeds inside `polygon` and at least `margin` from its boundary (a seed nearer its edge
// would make a sliver of a sub-block: its neighbours' cells take the place).
std::vector<Point> select_seeds(std::span<const Point> polygon, std::span<const Point> seeds, double margin);

// A straight crack the sub-blocks conform to: pairs of seeds mirrored across it, one pair every
// `spacing` (the crack's length over the nearest whole number of spacings, at least 2), half
// a spacing either side, from two spacings before its start to two after its end. The
// bisector of each pair is the crack's line, that of neighbouring pairs a perpendicular through
// it, so that the cells' faces run along the line, and meet it at the crack's two ends.
struct CrackSeeds {
  std::vector<Point> seeds;
  double spacing = 0.0;  // the spacing used
};
CrackSeeds make_crack_seeds(const Segment2& crack, double spacing);

// Whether other seeds near `p` would spoil a crack's faces: p within `spacing` of the crack
// extended by two spacings at each end (each point of the line then lies nearer its pair's
// seeds, at most spacing/√2 away, than to p).
bool lies_near_crack(Point p, const Segment2& crack, double spacing);

// Whether segment a–b lies on `crack` (both ends within `tolerance` of its line, its middle
// between the crack's ends).
bool lies_on_crack(Point a, Point b, const Segment2& crack, double tolerance);

// Two seeds that make a reflex corner of a polygon a node of their two cells: mirrored across
// the bisector of the corner's angle α (> 180°), each `size`/2 from the corner, at α/4 from
// the edge beside it. The corner is then equidistant from both, and so lies on their face
// (which runs along the bisector) where no other seed is as near it (a caller leaves out the
// seeds within `size` of it): each cell meets the corner with a convex angle α/2, and none wraps
// round it. A Voronoi cell that held the corner would be split there into convex parts, one of
// them as small as the cell's reach past the corner's lines.
struct ReflexCornerSeeds {
  Point corner;
  std::array<Point, 2> seeds;
};

// The seeds of each reflex corner of the simple counter-clockwise `polygon` (turning right by
// more than 1e-12 of its edges' lengths), in the order of its vertices; a corner whose seeds
// would lie outside the polygon, within `margin` of its outline or within `size`/2 of an
// earlier corner's seeds is left out (a narrow notch: its cells are split as before).
std::vector<ReflexCornerSeeds> make_reflex_corner_seeds(std::span<const Point> polygon, double size, double margin);

// A tessellated polygon: sub-block polygons (counter-clockwise) and, per sub-block and edge
// (vertex k → k + 1), where the edge lies: >= 0, the sub-block on its other side (a bond);
// < 0, on edge −1 − value of the tessellated polygon. Two sub-blocks beside a reflex corner
// may share two faces: the one facing an edge is that with the same ends, run the other way.
// `cell_of`: per sub-block, the Voronoi cell it is, or (triangles) the one it was fanned from.
struct Tessellation {
  std::vector<Polygon> cells;
  std::vector<std::vector<int>> edge_sources;
  std::vector<int> cell_of;
};

// The Voronoi cells of `seeds` (inside `polygon`) clipped to the simple counter-clockwise
// `polygon`, or those cells fanned into triangles.
//
// A convex polygon: each cell is the polygon clipped by the half-planes nearer its seed than
// another's (Sutherland–Hodgman, each edge carrying where it came from); the neighbours tried
// are those within 3 `size` (a jittered grid's cell lies within 2√2 size of its seed), more
// when a cell reaches farther: a bisector cuts a cell only if its seed lies within twice the
// cell's radius. Then vertices closer than 1e-2 size are welded (a face that short is dropped
// from both its sub-blocks), onto the polygon's corner or edge where one of them lies there,
// so that the cells fill the polygon exactly.
//   for each seed s: cell = polygon
//     for each other seed t within r, nearest first: cell ∩= {x : |x − s| <= |x − t|}
//     if 2 max|v − s| > r: r = 2 max|v − s|, again
//
// A polygon that is not convex: cut into convex pieces along diagonals (convex_pieces: Hertel
// & Mehlhorn 1983); every seed's cell clipped to every piece as above (a seed in one piece may
// own part of another), the edges on a seam labelled by the same seed's fragment across; a
// seed's fragments on two sides of a seam merged into one sub-block where their union is
// convex and meets each neighbour along one straight face (a cell is split only where it holds
// a reflex corner), the others left as sub-blocks bonded along the seam; then the vertices
// welded as above (the polygon's corners kept):
//   pieces = convex_pieces(polygon)
//   for each seed s, piece P: fragment(s, P) = the cell of s clipped to P, if not empty
//   until no merge is left, for each seam between fragment(s, P) and fragment(s, Q):
//     if fragment(s, P) ∪ fragment(s, Q) is convex with one face per neighbour: merge them
//   weld; a vertex that joined two outline edges goes onto their corner; a sub-block welded
//     to two vertices goes, its neighbours facing each other
//   drop the vertex between two edges facing one neighbour (from both)
// Two sub-blocks may then meet along two faces (each named on both sides), and a sub-block
// is convex up to the welding (a vertex up to 1e-2 size inside the line of its neighbours).
//
// Either way every face between two sub-blocks is named by both, every face on the outline
// by its edge. Throws std::invalid_argument for a polygon that is not counter-clockwise or
// not simple, or seeds that leave a sub-block degenerate.
Tessellation tessellate(std::span<const Point> polygon, std::span<const Point> seeds, double size, TessellationKind kind);

}  // namespace hydrodda::geometry
