#pragma once
// Cutting a domain polygon into blocks along straight fracture traces (the paper's §3.1), and
// shrinking the blocks along their fracture faces to open an initial aperture.

#include <optional>
#include <string>
#include <vector>

#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

struct CutResult {
  std::vector<Polygon> blocks;         // counter-clockwise, in a deterministic order
  // Per block, per edge (vertex k → k + 1): the index of the fracture it lies on, −1 for the
  // domain boundary. What per-fracture results and the aperture shrink read.
  std::vector<std::vector<int>> edge_fractures;
  std::vector<Segment2> used_traces;   // the fracture pieces that bound blocks
  std::vector<int> dropped_from;       // fractures with a piece that cut nothing, ascending
  std::vector<std::string> warnings;   // the same, as messages naming the fracture by its index
};

// Cuts `domain` (simple, counter-clockwise) by the fracture segments. A fracture may end inside
// the domain or on another fracture; pieces that separate nothing (dangling ends, traces wholly
// inside a block or a welded region, clusters of traces that touch none connected to the
// domain's boundary) are dropped with a warning; parts of fractures inside a `welded` polygon
// are ignored, so those regions stay whole.
//
// Algorithm (a planar arrangement, then its faces):
//   1. segments = domain edges + fracture parts inside the domain and outside welded regions
//   2. split every segment at its intersections with the others (candidate pairs from a grid
//      of their boxes); merge points closer than a relative 1e-9
//   3. repeat: remove edges with an end of degree 1 (dangling pieces), and edges not connected
//      to the domain boundary (an island of traces inside a block would make a block with a
//      hole, which no block can be: as a trace that does not cut a block through, it is
//      dropped); walk the faces; remove edges with the same face on both sides (bridges),
//      and the boundary of a cluster that a face goes round and touches at one vertex only
//      (the face would be a block with a hole, pinched there); until nothing changes
//   4. walk the faces: from half-edge u→v continue along the edge that follows v→u clockwise
//      around v; bounded faces come out counter-clockwise (area > 0), the outer one clockwise
CutResult cut_domain(const Polygon& domain, const std::vector<Segment2>& fractures,
                     const std::vector<Polygon>& welded);

// A block after the aperture: its polygon, and for each of its edges the edge of the block
// it lies along (an edge shorter than the aperture can vanish).
struct ShrunkBlock {
  Polygon polygon;
  std::vector<int> edges;
};

// The block moved inward by aperture / 2 along every edge with fracture_face[e] set (the others
// stay where they are), each new vertex where the offset lines of its two edges meet. An edge
// the offset turns around (a short edge between two faces at a shallow angle) is removed and
// its neighbours' lines meet instead, as a polygon offset does where an edge collapses (the
// edge event of a straight skeleton; Aichholzer et al. 1995). Empty when fewer than three
// edges are left or the block is turned inside out.
std::optional<ShrunkBlock> shrink_block(const Polygon& block, const std::vector<bool>& fracture_face, double aperture);

// Moves every block edge that does not lie on the domain boundary inward by aperture / 2, so
// that neighbours sharing a fracture face end up `aperture` apart and faces on the boundary
// stay on it. Throws std::runtime_error when a block is too small for the aperture (it would
// turn inside out).
std::vector<Polygon> shrink_blocks(const std::vector<Polygon>& blocks, const Polygon& domain, double aperture);

}  // namespace hydrodda::geometry
