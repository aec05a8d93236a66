#pragma once
// How often traces cross, estimated from their lengths and directions alone: a guard against
// a fractures file that would cut a domain into more blocks than can be made, checked before
// any cutting.

#include <span>

#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

// The crossings expected of the traces if each kept its length and direction and lay at a
// uniformly random place in `region` (of area A, large against the traces): two traces of
// lengths l_i, l_j at an angle φ cross where one's position falls in a parallelogram of area
// l_i l_j |sin φ| about the other, so
//   crossings = Σ_{i<j} l_i l_j |sin(θ_i − θ_j)| / A,
// summed over directions gathered into 1° bins (time linear in the traces). Each crossing
// can add at most one block to a cut, so this also bounds, roughly, the blocks the traces
// make. 0 for a region without area.
double estimate_crossings(std::span<const Segment2> traces, const Box& region);

}  // namespace hydrodda::geometry
