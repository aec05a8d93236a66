#pragma once
// The distance from a point to the nearest of many segments, where only distances under a
// reach matter: the size field of a mesh refined near fracture traces (refined_size() is the
// largest size at and beyond refine_distance). Gmsh asks it at every point it tries, some
// ten million times for a mesh of 10^6 triangles, and a seal's traces number in the
// thousands: a loop over every trace is the meshing's cost. The segments are indexed by a
// uniform grid over pieces of them at most 2 × reach long; a query visits only the pieces
// within reach and measures the distance to the whole segment each belongs to, so the answer
// is, bit for bit, the loop's wherever that is under the reach.
// Queries keep no state: Gmsh's threads may ask at once.

#include <span>
#include <vector>

#include "geometry/spatial_grid.hpp"
#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {

class LineDistance {
 public:
  LineDistance(std::span<const Segment> lines, double reach);

  // min over the segments of distance_to_segment(p, from, to) when that is under the reach;
  // otherwise some value at least the reach (infinity when no segment is within it).
  double nearest(geometry::Point p) const;

 private:
  std::vector<Segment> lines_;
  double reach_;
  std::vector<int> line_of_piece_;  // before grid_: the grid's initialiser fills it
  geometry::SpatialGrid grid_;
};

}  // namespace hydrodda::mesh
