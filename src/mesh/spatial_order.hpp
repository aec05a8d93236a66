#pragma once
// Renumbers a mesh's triangles and nodes so that neighbours in space are neighbours in memory.
// The mesher's numbering scatters them (Gmsh numbers in the order its Delaunay refinement
// inserts): every search over a grid of elements (the porosity clip, the face loads, the
// local apertures) then misses the cache at each element it reads. Along a Hilbert curve, the
// elements of a grid cell and of its neighbours lie together (the face loads of the
// 10^4-block seal over a structured 10^6-triangle mesh ran 2.7 times as long with its
// triangles numbered at random: bench_porosity's BM_SealFaceLoads).

#include <cstdint>

#include "mesh/triangle_mesh.hpp"

namespace hydrodda::mesh {

// Triangles in the order of their centroids along a Hilbert curve over the mesh's bounding
// square (2^16 cells a side; ties in the mesher's order), nodes in the order the triangles
// first use them (nodes no triangle uses last, in their order), with regions and boundary
// edges renumbered to match. Corners keep their order within each triangle. The same mesh
// always gives the same numbering.
void order_spatially(TriangleMesh& mesh);

// The distance along the Hilbert curve of order 16 of cell (x, y), 0 ≤ x, y < 2^16.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y);

}  // namespace hydrodda::mesh
