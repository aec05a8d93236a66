#include "dda/contact_detection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hydrodda::dda {

using geometry::Box;
using geometry::Point;

std::vector<std::pair<int, int>> find_block_pairs(std::span<const Box> boxes, double distance,
                                                  std::span<const char> skip) {
  std::vector<std::pair<int, int>> pairs;
  find_block_pairs(boxes, distance, skip, pairs);
  return pairs;
}

void find_block_pairs(std::span<const Box> boxes, double distance, std::span<const char> skip,
                      std::vector<std::pair<int, int>>& pairs) {
  // Uniform grid: cell = mean box extent; each box is entered in every cell it covers, the
  // (cell, block) list is sorted and pairs are read off within each cell, then deduplicated.
  const int n = static_cast<int>(boxes.size());
  pairs.clear();
  if (n < 2) return;
  Box all;
  double extent = 0.0;
  for (const Box& b : boxes) {
    all.add(b.lo);
    all.add(b.hi);
    extent += std::max(b.width(), b.height());
  }
  double cell = std::max(extent / n + distance, 1e-12);
  // Keep the cell count near the block count so memory stays linear.
  while ((all.width() / cell + 1) * (all.height() / cell + 1) > 4.0 * n + 16) cell *= 1.5;
  const auto nx = static_cast<std::int64_t>(all.width() / cell) + 1;
  thread_local std::vector<std::pair<std::int64_t, int>> entries;  // the memory kept from call to call
  entries.clear();
  for (int i = 0; i < n; ++i) {
    const Box b = boxes[i].inflated(distance / 2);
    const auto x0 = static_cast<std::int64_t>((b.lo.x - all.lo.x) / cell);
    const auto x1 = static_cast<std::int64_t>((b.hi.x - all.lo.x) / cell);
    const auto y0 = static_cast<std::int64_t>((b.lo.y - all.lo.y) / cell);
    const auto y1 = static_cast<std::int64_t>((b.hi.y - all.lo.y) / cell);
    for (auto y = std::max<std::int64_t>(y0, 0); y <= y1; ++y)
      for (auto x = std::max<std::int64_t>(x0, 0); x <= std::min(x1, nx); ++x)
        entries.emplace_back(y * (nx + 1) + x, i);
  }
  std::sort(entries.begin(), entries.end());
  for (std::size_t s = 0; s < entries.size();) {
    std::size_t e = s;
    while (e < entries.size() && entries[e].first == entries[s].first) ++e;
    for (std::size_t p = s; p < e; ++p) {
      for (std::size_t q = p + 1; q < e; ++q) {
        const int i = entries[p].second;
        const int j = entries[q].second;
        if (skip[i] && skip[j]) continue;
        if (boxes[i].inflated(distance).overlaps(boxes[j])) pairs.emplace_back(i, j);
      }
    }
    s = e;
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

namespace {

// Neighbours may dip below the edge line by this sine of angle and still count as outside.
constexpr double kWedgeTolerance = 0.05;
// Sine of the angle within which an incident edge counts as lying along the contact edge.
constexpr double kParallelTolerance = 0.05;
// Gaps to the two edges at a corner closer than this fraction of the contact distance tie.
constexpr double kCornerTieTolerance = 1e-3;
// Tributary lengths closer than this fraction of the coordinates' size are equal: their
// round-off, far below any face a contact carries.
constexpr double kShareRoundOff = 1e-12;

// Signed distance of p outside the line of edge (a, b) of a counter-clockwise polygon.
double compute_gap(Point p, Point a, Point b, double length) { return -geometry::orient(a, b, p) / length; }
double compute_gap(Point p, Point a, Point b) { return compute_gap(p, a, b, geometry::distance(a, b)); }

// Whether vertex p, `before` and `after` its neighbours on its own block, may touch the edge
// from a to b: both incident edges point away from the edge's block, within the wedge
// tolerance (a reflex vertex, or one whose own block lies across the edge's line, never
// touches that face).
bool may_touch(Point p, Point before, Point after, Point a, Point b) {
  const double length = geometry::distance(a, b);
  const Point n{(b.y - a.y) / length, -(b.x - a.x) / length};
  return dot(before - p, n) >= -kWedgeTolerance * geometry::distance(before, p) &&
         dot(after - p, n) >= -kWedgeTolerance * geometry::distance(after, p);
}

// Whether a vertex at `depth` behind the line of edge e of polygon `eb` entered by that edge:
// it lies inside the polygon and no other edge is nearer than e by more than `tie`, leaving
// out a nearer edge that the vertex cannot touch and lies deeper than the tie behind.
// An edge the vertex's own block lies across is no way in: a thin wedge's tip that entered by
// a face near its end lies nearer the corner's other edge, across which its block lies; taken
// as the nearest, that edge left the tip no contact at all, and it ran on into the block by
// millimetres a step. A vertex within the tie of such an edge stands on the block's boundary
// there, beside it (the corners of a tessellated rock's sub-blocks at a node, a hair apart
// along the face they share the line of): it entered by no edge, and e is no contact for it.
bool is_entrance_edge(Point p, Point before, Point after, std::span<const Point> eb, int e, double depth,
                      double tie) {
  if (!geometry::contains(eb, p)) return false;
  const int ne = static_cast<int>(eb.size());
  for (int f = 0; f < ne; ++f) {
    if (f == e) continue;
    const Point a = eb[f], b = eb[(f + 1) % ne];
    const double to_f = geometry::distance_to_segment(p, a, b);
    if (to_f + tie < depth && (to_f <= tie || may_touch(p, before, after, a, b))) return false;
  }
  return true;
}

// Whether no vertex of polygon `eb` lies nearer p than `reach` by more than `tie`: a corner
// past an edge's end touches that end only if the end is the nearest corner of the block.
// Where a block's straight side is split into collinear edges (joints meeting a bed), a corner
// at one junction lies on the line of the edge beyond the next, past its end by the short
// edge between, and within the contact distance; taken, it is a contact at a point where it
// has no face, preloaded by whatever the face carries, that no step can settle. Its nearest
// corner is the junction it stands at, whose own edges it touches.
bool is_nearest_corner(Point p, std::span<const Point> eb, double reach, double tie) {
  for (const Point q : eb)
    if (geometry::distance(p, q) + tie < reach) return false;
  return true;
}

// Whether a vertex behind the line of an edge lies past the convex corner at that edge's end:
// in front of the line of the corner's other edge, and so outside the block. At a junction of
// two straight joints the four blocks' corners meet; once the blocks slide a little along
// the joints, a corner of one lies past the corner of the block diagonally across, behind one
// of that block's edge lines by up to the sliding's share across it (the faulted seal at
// 2,000 m of head: 1.1e-5 m) but touching nothing. Taken against that edge, the depth reads as
// a penetration which no force on the contact can push out (the blocks beside it, in face
// contact along the same joint lines, hold the corner where it is), and the step is cut to
// nothing. Both gaps beyond round-off (`round_off`), so that coinciding corners keep their edge.
bool is_past_the_corner(double gap, double other_gap, double round_off) {
  return gap < -round_off && other_gap > round_off;
}

// Half the length, along the edge and inside it, of each face incident to the vertex that
// lies along the edge: the share of the face contact this vertex carries.
double compute_tributary_length(Point p, Point before, Point after, Point a, Point b,
                                double distance) {
  const FacesAlongEdge faces = find_faces_along_edge(p, before, after, a, b, distance);
  double total = 0.0;
  for (int k = 0; k < faces.count; ++k) total += 0.5 * std::abs(faces.face[k].far - faces.face[k].near);
  return total;
}

// Vertex v of polygon `va` (block a) against edge e of polygon `eb` (block b): the candidate
// appended to `out` if the vertex may touch the edge. Every candidate's vertex lies within
// `distance` of the edge as a segment: within it of the line, and past an end within it of
// that end.
void test_vertex_edge(std::span<const Point> va, int a, int v, std::span<const Point> eb, int b, int e,
                      double distance, double kept_depth, ContactCandidates& out) {
  const int nv = static_cast<int>(va.size());
  const int ne = static_cast<int>(eb.size());
  const Point p = va[v];
  const Point e0 = eb[e];
  const Point e1 = eb[(e + 1) % ne];
  const double length = geometry::distance(e0, e1);
  const double gap = compute_gap(p, e0, e1, length);
  if (gap > distance || gap < -distance) return;
  const double t = dot(p - e0, e1 - e0) / (length * length);
  const double slack = distance / length;
  if (t < -slack || t > 1 + slack) return;
  // The vertex's own block must lie outside the edge near the vertex: both incident edges
  // point away from block b (a reflex vertex never touches a face).
  const Point before = va[(v + nv - 1) % nv];
  const Point after = va[(v + 1) % nv];
  if (!may_touch(p, before, after, e0, e1)) return;
  // Behind the edge's line is a penetration only inside block b, and only of the edge the
  // vertex came in by, the nearest (Shi's entrance edge). Where the contact distance nears a
  // block's size, a vertex just beside b, or just inside it near another edge, also lies
  // within the distance behind b's far edges (a corner 1 mm to the left of a 0.64 m high
  // block sits 0.64 m "into" its bottom edge): a depth no cut of the step could settle. A
  // settled step leaves penetrations far below the corner tie, so real contacts of a running
  // model are never tested here; after the wedge test, as it is the dearer.
  const double tie = kCornerTieTolerance * distance;
  if (-gap > tie && !is_entrance_edge(p, before, after, eb, e, -gap, tie)) return;
  // At or past an end of the edge (vertex–vertex): keep only the entrance edge, the one of
  // the two edges meeting there whose line the vertex is farther outside (Shi 1988, §4.3).
  // Corners that coincide (side-by-side blocks) leave both gaps equal up to the motion of a
  // step; there the edge that carries a face contact wins (by more than round-off), then the
  // lower index, so the choice (and the contact's key and state) does not flip on round-off
  // from step to step. A vertex past the corner by less than the tie, and behind the edge's
  // line by no more than `kept_depth`, is a candidate marked kept_if_closed (the caller keeps
  // it or not by the contact's last state).
  bool kept_if_closed = false;
  if (t < tie / length || t > 1 - tie / length) {
    const bool at_start = t < 0.5;
    const int other = at_start ? (e + ne - 1) % ne : (e + 1) % ne;
    const Point other_a = eb[other];
    const Point other_b = eb[(other + 1) % ne];
    const double other_gap = compute_gap(p, other_a, other_b);
    if (other_gap > gap + tie) return;
    if (other_gap >= gap - tie) {
      // The tributary lengths only here, where they break the tie: a contact's own is made
      // when it closes (tributary_length), not for every candidate of every step.
      // Shares within their round-off are equal: a corner that meets only a corner (blocks
      // diagonally across a junction of joints) has none on either edge, and round-off (1e-17
      // against 1e-32 m) would otherwise pick one edge in one step and the other in the next.
      const double length_share = compute_tributary_length(p, before, after, e0, e1, distance);
      const double other_share = compute_tributary_length(p, before, after, other_a, other_b, distance);
      const double share_tie = kShareRoundOff * (std::abs(p.x) + std::abs(p.y) + distance);
      if (other_share > length_share + share_tie) return;
      if (other_share >= length_share - share_tie) {
        // Neither edge carries a face (corner on corner): the edge of the two that the corner
        // has passed beyond is none, even within the tie; else the lower index.
        const Point corner = at_start ? e0 : e1;
        const Point into = at_start ? other_a : e0;
        const Point out_of = at_start ? e1 : other_b;
        const bool convex = cross(corner - into, out_of - corner) > 0.0;
        if (convex && is_past_the_corner(gap, other_gap, share_tie)) {
          if (geometry::distance(p, corner) > tie || -gap > kept_depth) return;
          kept_if_closed = true;
        } else if (!(convex && is_past_the_corner(other_gap, gap, share_tie)) && other < e) {
          return;
        }
      }
    }
    if (t < 0 || t > 1) {
      const double to_end = geometry::distance(p, at_start ? e0 : e1);
      if (to_end > distance || !is_nearest_corner(p, eb, to_end, tie)) return;
    }
  }
  ContactCandidate c;
  c.key = {a, v, b, e};
  c.edge_ratio = std::clamp(t, 0.0, 1.0);
  c.penetration = -gap;
  c.kept_if_closed = kept_if_closed;
  out.push_back(c);
}

// Vertices of polygon `va` within `reach` of edges of polygon `eb`, vertex by vertex, edges in
// order. A box test rejects most combinations before any division or square root.
void find_one_way_combinations(std::span<const Point> va, std::span<const Point> eb, double reach,
                               std::vector<VertexEdge>& out) {
  const int nv = static_cast<int>(va.size());
  const int ne = static_cast<int>(eb.size());
  thread_local std::vector<Box> boxes;  // each edge's box grown by the reach
  boxes.resize(ne);
  for (int e = 0; e < ne; ++e) {
    Box box;
    box.add(eb[e]);
    box.add(eb[(e + 1) % ne]);
    boxes[e] = box.inflated(reach);
  }
  const double reach_squared = reach * reach;
  for (int v = 0; v < nv; ++v) {
    const Point p = va[v];
    for (int e = 0; e < ne; ++e) {
      if (!boxes[e].contains(p)) continue;
      // The squared distance to the nearest point of the segment.
      const Point a = eb[e];
      const Point ab = eb[(e + 1) % ne] - a;
      const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
      const Point off = p - (a + t * ab);
      if (dot(off, off) <= reach_squared) out.push_back({v, e});
    }
  }
}

}  // namespace

FacesAlongEdge find_faces_along_edge(Point p, Point before, Point after, Point a, Point b, double distance) {
  const Point ab = b - a;
  const double length = geometry::norm(ab);
  const Point s = ab / length;
  const double tp = dot(p - a, s);
  FacesAlongEdge faces;
  for (Point q : {before, after}) {
    const Point pq = q - p;
    const double lq = geometry::norm(pq);
    if (std::abs(cross(s, pq)) > kParallelTolerance * lq) continue;
    if (std::abs(compute_gap(q, a, b)) > distance) continue;
    const double tq = dot(q - a, s);
    faces.face[faces.count++] = {std::clamp(tp, 0.0, length), std::clamp(tq, 0.0, length)};
  }
  return faces;
}

double tributary_length(std::span<const Point> va, int vertex, std::span<const Point> eb, int edge, double distance) {
  const int nv = static_cast<int>(va.size());
  const int ne = static_cast<int>(eb.size());
  return compute_tributary_length(va[vertex], va[(vertex + nv - 1) % nv], va[(vertex + 1) % nv], eb[edge],
                                  eb[(edge + 1) % ne], distance);
}

std::size_t find_vertex_edge_combinations(std::span<const Point> polygon_a, std::span<const Point> polygon_b,
                                          double reach, std::vector<VertexEdge>& out) {
  const std::size_t first = out.size();
  find_one_way_combinations(polygon_a, polygon_b, reach, out);
  const std::size_t a_on_b = out.size() - first;
  find_one_way_combinations(polygon_b, polygon_a, reach, out);
  return a_on_b;
}

void find_pair_contacts(std::span<const Point> polygon_a, int a, std::span<const Point> polygon_b, int b,
                        double distance, std::span<const VertexEdge> combinations, std::size_t a_on_b,
                        ContactCandidates& out, double kept_depth) {
  const std::size_t first = out.size();
  for (std::size_t k = 0; k < a_on_b; ++k)
    test_vertex_edge(polygon_a, a, combinations[k].vertex, polygon_b, b, combinations[k].edge, distance, kept_depth, out);
  const std::size_t second = out.size();
  for (std::size_t k = a_on_b; k < combinations.size(); ++k)
    test_vertex_edge(polygon_b, b, combinations[k].vertex, polygon_a, a, combinations[k].edge, distance, kept_depth, out);
  // A corner of b on a corner of a already in contact is the same contact point seen from the
  // other block: an edge–edge contact is one vertex–edge contact at each end of the overlap
  // (Shi 1988, §4.3). Counted twice it would double the stiffness there and the cohesion and
  // tensile strength of the face (each carries half the face's length). a's is kept.
  const double tie = kCornerTieTolerance * distance;
  const auto same_corner = [&](const ContactCandidate& from_b) {
    const Point p = polygon_b[from_b.key.vertex];
    for (std::size_t k = first; k < second; ++k)
      if (!out[k].kept_if_closed && geometry::distance(polygon_a[out[k].key.vertex], p) <= tie) return true;
    return false;
  };
  out.erase(std::remove_if(out.begin() + static_cast<std::ptrdiff_t>(second), out.end(), same_corner), out.end());
}

void find_pair_contacts(std::span<const Point> polygon_a, int a, std::span<const Point> polygon_b, int b,
                        double distance, ContactCandidates& out, double kept_depth) {
  thread_local std::vector<VertexEdge> combinations;
  combinations.clear();
  const std::size_t a_on_b =
      find_vertex_edge_combinations(polygon_a, polygon_b, contact_reach(distance), combinations);
  find_pair_contacts(polygon_a, a, polygon_b, b, distance, combinations, a_on_b, out, kept_depth);
}

}  // namespace hydrodda::dda
