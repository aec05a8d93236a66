#pragma once
// Cutting a domain polygon into blocks along straight fracture traces (the paper's §3.1), and
// shrinking the blocks along their fracture faces to open an initial aperture.

#include <string>
#include <vector>

#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

struct Segment2 {
  Point from;
  Point to;
};

struct CutResult {
  std::vector<Polygon> blocks;         // counter-clockwise, in a deterministic order
  std::vector<Segment2> used_traces;   // the fracture pieces that bound blocks
  std::vector<std::string> warnings;   // fracture pieces that cut nothing, dropped
};

// Cuts `domain` (simple, counter-clockwise) by the fracture segments. A fracture may end inside
// the domain or on another fracture; pieces that separate nothing (dangling ends, traces wholly
// inside a block or a welded region) are dropped with a warning; parts of fractures inside a
// `welded` polygon are ignored, so those regions stay whole.
//
// Algorithm (a planar arrangement, then its faces):
//   1. segments = domain edges + fracture parts inside the domain and outside welded regions
//   2. split every segment at its intersections with the others; merge coincident points
//   3. repeatedly remove edges with an end of degree 1 (dangling pieces)
//   4. walk the faces: from half-edge u→v continue along the edge that follows v→u clockwise
//      around v; bounded faces come out counter-clockwise (area > 0), the outer one clockwise
CutResult cut_domain(const Polygon& domain, const std::vector<Segment2>& fractures,
                     const std::vector<Polygon>& welded);

// Moves every block edge that does not lie on the domain boundary inward by aperture / 2, so
// that neighbours sharing a fracture face end up `aperture` apart and faces on the boundary
// stay on it. Each new vertex is where the offset lines of its two edges meet. Throws
// std::runtime_error when a block is too small for the aperture (it would turn inside out).
std::vector<Polygon> shrink_blocks(const std::vector<Polygon>& blocks, const Polygon& domain, double aperture);

}  // namespace hydrodda::geometry
