#pragma once
// The local fracture aperture at each fluid element, for the cubic law.
//
// For an element with open area, w_e = s_1 + s_2: the two smallest signed distances from the
// element's centroid to two different blocks (negative inside a block). Between two parallel
// faces a distance w apart this is exactly w wherever the centroid lies, in the gap or inside
// either block, so the cubic law's transmissivity does not depend on how the element sits
// across the fracture. Where fewer than two blocks are within reach, the domain boundary is a
// wall too (a block pulled away from it leaves a gap against it). The two nearest walls must
// face each other (their distances grow in opposite directions, within 45°); where they do
// not, the narrowest open gap between facing walls, the domain boundary among them, is taken:
// an element along the boundary, its centroid in a block that has moved a little off the
// boundary, has the sliver the block left, not the distance to the block across a fracture
// behind it.

#include <array>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::coupling {

// Per element: the local aperture (m), 0 where the element has no open area.
// `reach`: how far from a centroid walls are looked for; beyond it a wall is taken at `reach`.
std::vector<double> compute_local_apertures(std::span<const geometry::Point> centroids,
                                            std::span<const double> fracture_area,
                                            std::span<const geometry::Polygon> blocks,
                                            const geometry::Polygon& domain, double reach);
// The same at the centroids of a mesh's elements (made as they are needed).
std::vector<double> compute_local_apertures(const mesh::TriangleMesh& mesh, std::span<const double> fracture_area,
                                            std::span<const geometry::Polygon> blocks,
                                            const geometry::Polygon& domain, double reach);

// Signed distance from p to a simple polygon: negative inside.
double signed_distance(geometry::Point p, std::span<const geometry::Point> polygon);

}  // namespace hydrodda::coupling
