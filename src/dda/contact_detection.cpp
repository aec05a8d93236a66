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

// Signed distance of p outside the line of edge (a, b) of a counter-clockwise polygon.
double compute_gap(Point p, Point a, Point b, double length) { return -geometry::orient(a, b, p) / length; }
double compute_gap(Point p, Point a, Point b) { return compute_gap(p, a, b, geometry::distance(a, b)); }

// Half the length, along the edge and inside it, of each face incident to the vertex that
// lies along the edge: the share of the face contact this vertex carries.
double compute_tributary_length(Point p, Point before, Point after, Point a, Point b,
                                double distance) {
  const Point ab = b - a;
  const double length = geometry::norm(ab);
  const Point s = ab / length;
  const double tp = dot(p - a, s);
  double total = 0.0;
  for (Point q : {before, after}) {
    const Point pq = q - p;
    const double lq = geometry::norm(pq);
    if (std::abs(cross(s, pq)) > kParallelTolerance * lq) continue;
    if (std::abs(compute_gap(q, a, b)) > distance) continue;
    const double tq = dot(q - a, s);
    const double lo = std::clamp(std::min(tp, tq), 0.0, length);
    const double hi = std::clamp(std::max(tp, tq), 0.0, length);
    total += 0.5 * (hi - lo);
  }
  return total;
}

// An edge of the polygon whose edges are searched, with what every vertex test needs of it.
struct EdgeFrame {
  Point a, b;
  double length;
  // The edge's box grown by twice the contact distance. The tests below admit a vertex up to
  // the distance off the edge's line and past its ends, at most √2 × the distance from the
  // edge's box along either axis, so a vertex outside this box cannot pass them.
  Box reach;
};

// Vertices of polygon `va` against edges of polygon `eb`. The edges' lengths and reach are
// computed once per pair rather than once per vertex–edge test, and the box test rejects most
// vertex–edge pairs before any division or square root (bench_dda: detection was an eighth
// of a wall's step).
void find_one_way(std::span<const Point> va, int a, std::span<const Point> eb, int b,
                  double distance, ContactCandidates& out) {
  const int nv = static_cast<int>(va.size());
  const int ne = static_cast<int>(eb.size());
  thread_local std::vector<EdgeFrame> edges;
  edges.resize(ne);
  for (int e = 0; e < ne; ++e) {
    EdgeFrame& f = edges[e];
    f.a = eb[e];
    f.b = eb[(e + 1) % ne];
    f.length = geometry::distance(f.a, f.b);
    f.reach = Box{};
    f.reach.add(f.a);
    f.reach.add(f.b);
    f.reach = f.reach.inflated(2.0 * distance);
  }
  for (int v = 0; v < nv; ++v) {
    const Point p = va[v];
    const Point before = va[(v + nv - 1) % nv];
    const Point after = va[(v + 1) % nv];
    for (int e = 0; e < ne; ++e) {
      const EdgeFrame& edge = edges[e];
      if (!edge.reach.contains(p)) continue;
      const Point e0 = edge.a;
      const Point e1 = edge.b;
      const double length = edge.length;
      const double gap = compute_gap(p, e0, e1, length);
      if (gap > distance || gap < -distance) continue;
      const double t = dot(p - e0, e1 - e0) / (length * length);
      const double slack = distance / length;
      if (t < -slack || t > 1 + slack) continue;
      // The vertex's own block must lie outside the edge near the vertex: both incident
      // edges point away from block b (a reflex vertex never touches a face).
      const Point n{(e1.y - e0.y) / length, -(e1.x - e0.x) / length};
      if (dot(before - p, n) < -kWedgeTolerance * geometry::distance(before, p)) continue;
      if (dot(after - p, n) < -kWedgeTolerance * geometry::distance(after, p)) continue;
      const double length_share = compute_tributary_length(p, before, after, e0, e1, distance);
      // At or past an end of the edge (vertex–vertex): keep only the entrance edge, the one of
      // the two edges meeting there whose line the vertex is farther outside (Shi 1988, §4.3).
      // Corners that coincide (side-by-side blocks) leave both gaps equal up to the motion of
      // a step; there the edge that carries a face contact wins, then the lower index, so the
      // choice (and the contact's key and state) does not flip on round-off from step to step.
      const double tie = kCornerTieTolerance * distance;
      if (t < tie / length || t > 1 - tie / length) {
        const bool at_start = t < 0.5;
        const int other = at_start ? (e + ne - 1) % ne : (e + 1) % ne;
        const Point other_a = eb[other];
        const Point other_b = eb[(other + 1) % ne];
        const double other_gap = compute_gap(p, other_a, other_b);
        if (other_gap > gap + tie) continue;
        if (other_gap >= gap - tie) {
          const double other_share = compute_tributary_length(p, before, after, other_a, other_b, distance);
          if (other_share > length_share || (other_share == length_share && other < e)) continue;
        }
        if ((t < 0 || t > 1) && geometry::distance(p, at_start ? e0 : e1) > distance) continue;
      }
      ContactCandidate c;
      c.key = {a, v, b, e};
      c.edge_ratio = std::clamp(t, 0.0, 1.0);
      c.penetration = -gap;
      c.length = length_share;
      out.push_back(c);
    }
  }
}

}  // namespace

void find_pair_contacts(std::span<const Point> polygon_a, int a,
                        std::span<const Point> polygon_b, int b, double distance,
                        ContactCandidates& out) {
  const std::size_t first = out.size();
  find_one_way(polygon_a, a, polygon_b, b, distance, out);
  const std::size_t second = out.size();
  find_one_way(polygon_b, b, polygon_a, a, distance, out);
  // A corner of b on a corner of a already in contact is the same contact point seen from the
  // other block: an edge–edge contact is one vertex–edge contact at each end of the overlap
  // (Shi 1988, §4.3). Counted twice it would double the stiffness there and the cohesion and
  // tensile strength of the face (each carries half the face's length). a's is kept.
  const double tie = kCornerTieTolerance * distance;
  const auto same_corner = [&](const ContactCandidate& from_b) {
    const Point p = polygon_b[from_b.key.vertex];
    for (std::size_t k = first; k < second; ++k)
      if (geometry::distance(polygon_a[out[k].key.vertex], p) <= tie) return true;
    return false;
  };
  out.erase(std::remove_if(out.begin() + static_cast<std::ptrdiff_t>(second), out.end(), same_corner), out.end());
}

}  // namespace hydrodda::dda
