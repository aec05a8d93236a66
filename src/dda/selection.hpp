#pragma once
// Selecting block vertices and edges that lie on a segment: how "every block vertex on
// boundary X" in a scenario becomes fixed points, displacements or tractions.

#include <optional>
#include <span>
#include <vector>

#include "dda/definitions.hpp"

namespace hydrodda::dda {

struct VertexRef {
  int block = 0;
  int vertex = 0;
  friend bool operator==(const VertexRef&, const VertexRef&) = default;
};
struct EdgeRef {
  int block = 0;
  int edge = 0;  // from vertex edge to edge + 1
  friend bool operator==(const EdgeRef&, const EdgeRef&) = default;
};

// Vertices within `tolerance` of the closed segment ab, in block then vertex order.
std::vector<VertexRef> select_vertices_on_segment(std::span<const BlockDefinition> blocks,
                                                  Point a, Point b, double tolerance);

// Edges whose both ends lie within `tolerance` of the closed segment ab.
std::vector<EdgeRef> select_edges_on_segment(std::span<const BlockDefinition> blocks, Point a,
                                             Point b, double tolerance);

// Uniform or linearly varying traction on every edge on segment ab: normal and shear go
// linearly from their value at a to their value at b (end moments come from a linear normal);
// each may be a time table, the edge's ends then tables of the same path.
std::vector<EdgeTraction> make_tractions_on_segment(std::span<const BlockDefinition> blocks,
                                                    Point a, Point b, double tolerance,
                                                    const numerics::TimeTable& normal_a, const numerics::TimeTable& normal_b,
                                                    const numerics::TimeTable& shear_a, const numerics::TimeTable& shear_b);

// A roller at every block vertex on segment ab, its normal the segment's, pointing away from
// the block. With an initial stress, each starts pushing its vertex in by the field's normal
// traction over its share of the block's faces along the segment (compute_face_load).
std::vector<Roller> make_rollers_on_segment(std::span<const BlockDefinition> blocks, Point a, Point b,
                                            double tolerance, const std::optional<StressField>& initial_stress);

}  // namespace hydrodda::dda
