#pragma once
// The fixed fluid mesh: linear triangles with region tags and named boundary edges.

#include <array>
#include <string>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::mesh {

using geometry::Point;

// An edge of the mesh boundary (it belongs to one triangle only). `boundary` indexes
// TriangleMesh::boundary_names, or is kUnnamed when the edge lies on no named segment.
struct BoundaryEdge {
  static constexpr int kUnnamed = -1;
  std::array<int, 2> nodes{};
  int boundary = kUnnamed;
};

struct TriangleMesh {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;  // node indices, counter-clockwise
  std::vector<int> region;                    // per triangle, indexes region_names
  std::vector<std::string> region_names;      // region 0 is the part of no named region
  std::vector<BoundaryEdge> boundary_edges;
  std::vector<std::string> boundary_names;

  int node_count() const { return static_cast<int>(nodes.size()); }
  int triangle_count() const { return static_cast<int>(triangles.size()); }
};

// Area of triangle t (positive for a counter-clockwise triangle).
double triangle_area(const TriangleMesh& mesh, int t);
Point triangle_centroid(const TriangleMesh& mesh, int t);

// Index of a named boundary or region; -1 when the mesh has none of that name.
int find_boundary(const TriangleMesh& mesh, const std::string& name);
int find_region(const TriangleMesh& mesh, const std::string& name);

// Triangles whose region tag is the named region's; throws when the name is unknown.
std::vector<int> select_region(const TriangleMesh& mesh, const std::string& name);

// The edges that belong to exactly one triangle, each oriented as in its triangle (so that
// the domain lies to the left), in a deterministic order (sorted by node pair).
std::vector<std::array<int, 2>> find_boundary_edges(
    const std::vector<std::array<int, 3>>& triangles);
// The same edges, in the same order, each with the triangle it belongs to.
struct BoundarySide {
  std::array<int, 2> edge;  // oriented as in its triangle
  int triangle = 0;
};
std::vector<BoundarySide> find_boundary_sides(const std::vector<std::array<int, 3>>& triangles);

// Checks the invariants every consumer relies on: node indices in range, counter-clockwise
// triangles of positive area, one region tag per triangle, boundary indices in range.
// Throws std::runtime_error naming the first violation.
void validate(const TriangleMesh& mesh);

}  // namespace hydrodda::mesh
