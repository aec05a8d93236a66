#pragma once
// How many triangles a MeshRequest will give, before Gmsh is asked: a mesh of element size h
// has about c / h² triangles per unit area, so
//
//   N ≈ c ∫_domain dA / h(x)²,   h(x) = refined_size(request, distance to the nearest line).
//
// c = 2.65 is Gmsh's Delaunay (algorithm 5) as measured: 1,077,440 triangles on the 100 m ×
// 20 m seal at h = 0.07 m uniform (an equilateral triangle of side h would give 4/√3 = 2.31).
// The integral is taken on a grid of cells over the domain, the distance to the nearest line
// found for each cell within refine_distance of one (lines walked row by row over their band
// only), and 1/h² averaged across each cell's range of distances exactly: for h linear in d,
// the mean of 1/h² over [a, b] is 1/(h(a) h(b)), so a cell wider than the finest triangles
// still weighs the band correctly. Within a factor 1.5 of Gmsh's count on the meshes of
// tests/mesh/mesh_estimate_test.cpp.

#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {

struct TriangleEstimate {
  double near_lines = 0.0;  // within refine_distance of a refinement line (fracture_size there)
  double elsewhere = 0.0;   // the rest of the domain, at size
  double near_points = 0.0;  // what the refinement points add
  double total() const { return near_lines + elsewhere + near_points; }
};

TriangleEstimate estimate_triangle_count(const MeshRequest& request);

}  // namespace hydrodda::mesh
