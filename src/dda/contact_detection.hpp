#pragma once
// Contact detection: a broad phase on a uniform grid of block bounding boxes (never all pairs)
// and a narrow phase finding vertex–edge contacts, vertex–vertex ones included through the
// entrance-edge rule (Shi 1988, §4). Pure functions of polygons.

#include <array>
#include <compare>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::dda {

// A contact is vertex `vertex` of block `block_i` against edge `edge` (vertex edge → edge+1)
// of block `block_j`; its state carries from step to step under this key.
struct ContactKey {
  int block_i = 0;
  int vertex = 0;
  int block_j = 0;
  int edge = 0;
  friend auto operator<=>(const ContactKey&, const ContactKey&) = default;
};

struct ContactCandidate {
  ContactKey key;
  double edge_ratio = 0.0;   // projection of the vertex on the edge, 0 at its first vertex
  double penetration = 0.0;  // > 0 inside block_j, < 0 a gap
  // A vertex a hair past a corner of block_j (within the corner tie of it, and behind this
  // edge's line by no more than find_pair_contacts' kept_depth): no contact by the
  // entrance-edge rule, but one its caller may keep while it stays closed (a hysteresis in the
  // contact's existence: System::drop_corner_candidates_not_kept).
  bool kept_if_closed = false;
};

using ContactCandidates = std::vector<ContactCandidate>;

// Pairs (i < j) of blocks whose boxes, grown by `distance`, overlap; pairs of two blocks that
// both have skip[i] set (fixed blocks) are left out. Sorted, into `pairs` (its old contents
// replaced, its memory reused).
void find_block_pairs(std::span<const geometry::Box> boxes, double distance, std::span<const char> skip,
                      std::vector<std::pair<int, int>>& pairs);
std::vector<std::pair<int, int>> find_block_pairs(std::span<const geometry::Box> boxes,
                                                  double distance,
                                                  std::span<const char> skip);

// Every contact's vertex lies within the contact distance of its edge as a segment (within it
// of the edge's line, and past an end within it of that end). A list of vertex–edge
// combinations within this reach, round-off allowed for, holds all the pair's contacts.
inline double contact_reach(double distance) { return distance * (1.0 + 1e-9); }

// The faces incident to vertex p of a polygon (before → p and p → after) that lie along the
// edge ab of another (parallel within a sine of 0.05, their far ends within `distance` of its
// line), each as its part inside the edge: from p's projection (near) to the far end, in
// metres along ab from a. A vertex–edge contact carries half of each (its tributary length).
struct FaceAlongEdge {
  double near = 0.0;
  double far = 0.0;
};
struct FacesAlongEdge {
  int count = 0;
  std::array<FaceAlongEdge, 2> face{};
};
FacesAlongEdge find_faces_along_edge(geometry::Point p, geometry::Point before, geometry::Point after,
                                     geometry::Point a, geometry::Point b, double distance);

// The tributary length of vertex `vertex` of polygon `va` against edge `edge` of polygon `eb`:
// half of each face incident to the vertex that lies along the edge (find_faces_along_edge),
// the length of face contact the vertex carries, on which cohesion and tensile strength act.
// Made for the contacts that close, not by the search for every candidate.
double tributary_length(std::span<const geometry::Point> va, int vertex, std::span<const geometry::Point> eb, int edge,
                        double distance);

// A vertex of one polygon and an edge (edge → edge + 1) of another.
struct VertexEdge {
  int vertex = 0;
  int edge = 0;
};

// The combinations of a vertex of a with an edge of b, then of a vertex of b with an edge of
// a, whose vertex lies within `reach` of the edge as a segment; appended to `out`, vertex by
// vertex, edges in order. Returns how many are a's vertices on b's edges.
std::size_t find_vertex_edge_combinations(std::span<const geometry::Point> polygon_a,
                                          std::span<const geometry::Point> polygon_b, double reach,
                                          std::vector<VertexEdge>& out);

// No candidate marked kept_if_closed (find_pair_contacts' kept_depth).
inline constexpr double kNoCornerMemory = -std::numeric_limits<double>::infinity();

// Vertex–edge contacts of the pair (a, b), both ways, within `distance`, appended to `out`:
// among all the pair's combinations, or among those of `combinations` (its first `a_on_b`
// a's vertices on b's edges, the rest b's on a's). Given every combination within
// contact_reach(distance), the two find the same contacts. A vertex a hair past a corner, no
// deeper behind the edge's line than `kept_depth`, is a candidate marked kept_if_closed.
void find_pair_contacts(std::span<const geometry::Point> polygon_a, int a,
                        std::span<const geometry::Point> polygon_b, int b, double distance,
                        ContactCandidates& out, double kept_depth = kNoCornerMemory);
void find_pair_contacts(std::span<const geometry::Point> polygon_a, int a,
                        std::span<const geometry::Point> polygon_b, int b, double distance,
                        std::span<const VertexEdge> combinations, std::size_t a_on_b, ContactCandidates& out,
                        double kept_depth = kNoCornerMemory);

}  // namespace hydrodda::dda
