#include "coupling/pressure_forces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "coupling/force_moments.hpp"
#include "numerics/parallel.hpp"
#include "hydro/element_pressure.hpp"
#include "mesh/point_locator.hpp"

namespace hydrodda::coupling {

namespace {

// About 50 µs of work a block: from this many on, more threads pay for waking them.
constexpr std::size_t kBlocksWorthTwoThreads = 64;

// A piece of a segment inside one element: parameters t0 < t1 along it.
struct SegmentPiece {
  double t0, t1;
  int element;
};

// The part of segment a + t (b − a), t in [0, 1], inside triangle (p0, p1, p2), its edges
// widened by `tolerance` (a distance), by clipping against the triangle's three half-planes
// (Cyrus & Beck 1978); empty when it has no length.
std::optional<std::pair<double, double>> clip_segment(Point a, Point b, Point p0, Point p1, Point p2,
                                                      double tolerance) {
  if (geometry::orient(p0, p1, p2) < 0.0) std::swap(p1, p2);
  double t0 = 0.0, t1 = 1.0;
  const Point corners[3] = {p0, p1, p2};
  for (int k = 0; k < 3; ++k) {
    const Point p = corners[k], q = corners[(k + 1) % 3];
    // L × (signed distance inside the edge pq + tolerance) at the segment's ends.
    const double widen = tolerance * geometry::distance(p, q);
    const double fa = geometry::orient(p, q, a) + widen;
    const double fb = geometry::orient(p, q, b) + widen;
    if (fa < 0.0 && fb < 0.0) return std::nullopt;
    if (fa < 0.0) t0 = std::max(t0, fa / (fa - fb));       // enters here
    else if (fb < 0.0) t1 = std::min(t1, fa / (fa - fb));  // leaves here
  }
  if (!(t1 > t0)) return std::nullopt;
  return std::pair{t0, t1};
}

template <class Side>
std::vector<geometry::Box> side_boxes(const std::vector<Side>& sides) {
  std::vector<geometry::Box> boxes;
  for (const auto& side : sides) {
    geometry::Box box;
    box.add(side.a);
    box.add(side.b);
    boxes.push_back(box);
  }
  return boxes;
}

}  // namespace

// Boundary edges (in one triangle only), each with its triangle: built once per mesh.
std::vector<FacePressureLoads::BoundarySide> FacePressureLoads::find_boundary(const mesh::TriangleMesh& mesh) {
  std::vector<BoundarySide> boundary;
  for (const mesh::BoundarySide& side : mesh::find_boundary_sides(mesh.triangles)) {
    const auto [first, second] = std::minmax(side.edge[0], side.edge[1]);
    const int t = side.triangle;
    const Point a = mesh.nodes[first], b = mesh.nodes[second];
    // The unit normal pointing away from the triangle's third corner: out of the mesh.
    int third = 0;
    while (mesh.triangles[t][third] == first || mesh.triangles[t][third] == second) ++third;
    Point out = Point{b.y - a.y, a.x - b.x} / geometry::distance(a, b);
    if (dot(out, mesh.nodes[mesh.triangles[t][third]] - a) > 0.0) out = -1.0 * out;
    boundary.push_back({a, b, t, out});
  }
  return boundary;
}

FacePressureLoads::FacePressureLoads(const mesh::TriangleMesh& mesh)
    : FacePressureLoads(mesh, std::make_shared<const ElementIndex>(mesh.nodes, mesh.triangles)) {}

FacePressureLoads::FacePressureLoads(const mesh::TriangleMesh& mesh, std::shared_ptr<const ElementIndex> elements)
    : mesh_(mesh),
      elements_(std::move(elements)),
      boundary_(find_boundary(mesh)),
      boundary_grid_(side_boxes(boundary_)) {
  geometry::Box all;
  for (Point p : mesh.nodes) all.add(p);
  const double extent = std::max(all.width(), all.height());
  tolerance_ = 1e-12 * extent;
  area_tolerance_ = mesh::locator_area_tolerance(extent);
  // The grid holds about two elements a cell: cells of about √(2 × box area / elements).
  chunk_length_ = mesh.triangles.empty()
                      ? extent
                      : std::sqrt(2.0 * std::max(all.width() * all.height(), 1e-300) / mesh.triangles.size());
  for (const BoundarySide& side : boundary_) boundary_reach_ += geometry::distance(side.a, side.b);
  if (!boundary_.empty()) boundary_reach_ /= static_cast<double>(boundary_.size());
}

double FacePressureLoads::pressure_outside_mesh(Point p, std::span<const double> nodal_pressure) const {
  // The nearest boundary side, the first in order on a tie, through the grid of their boxes.
  const int nearest = boundary_grid_.nearest(
      p, boundary_reach_, [&](int k) { return geometry::distance_to_segment(p, boundary_[k].a, boundary_[k].b); });
  if (nearest < 0) throw std::invalid_argument("pressure forces: the fluid mesh has no elements");
  const BoundarySide& side = boundary_[nearest];
  return hydro::interpolate_pressure(mesh_, nodal_pressure, side.triangle,
                                     geometry::closest_point_on_segment(p, side.a, side.b));
}

std::vector<double> FacePressureLoads::cut_where_nearest_side_changes(Point a, Point b) const {
  // The nearest mesh point moves along one boundary side at a time; it passes from one to the
  // next about where a boundary node projects onto ab. Only nodes near the segment count: those
  // within its ends' distance from the mesh (and a little more) of it.
  std::vector<double> cuts{0.0, 1.0};
  const Point along = b - a;
  const double length_squared = dot(along, along);
  if (length_squared == 0.0) return cuts;
  // Both through the grid of the sides' boxes: a side within d of a point has its box within
  // d of it (the same nearest side and the same nodes as a look at every side).
  const auto distance_to_mesh = [&](Point p) {
    const auto distance = [&](int k) { return geometry::distance_to_segment(p, boundary_[k].a, boundary_[k].b); };
    const int nearest = boundary_grid_.nearest(p, boundary_reach_, distance);
    return nearest < 0 ? std::numeric_limits<double>::infinity() : distance(nearest);
  };
  const double reach = std::max(distance_to_mesh(a), distance_to_mesh(b));
  geometry::Box around;
  around.add(a);
  around.add(b);
  boundary_grid_.for_each_overlap(around.inflated(2.0 * reach + tolerance_), [&](int k) {
    for (Point node : {boundary_[k].a, boundary_[k].b}) {
      if (geometry::distance_to_segment(node, a, b) > 2.0 * reach + tolerance_) continue;
      const double t = dot(node - a, along) / length_squared;
      if (t > 0.0 && t < 1.0) cuts.push_back(t);
    }
  });
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

double FacePressureLoads::pressure_at(Point p, std::span<const double> nodal_pressure) const {
  // The lowest-numbered element holding p (within tolerance_ of its edges), through the
  // elements' grid: the rule mesh::PointLocator follows, without a second grid of the mesh.
  int t = -1;
  const double slack = std::sqrt(area_tolerance_);
  elements_->grid().for_each_overlap(geometry::Box{{p.x - slack, p.y - slack}, {p.x + slack, p.y + slack}}, [&](int e) {
    if (t >= 0 && e > t) return;
    const auto [a, b, c] = elements_->corners(e);
    if (mesh::triangle_holds(a, b, c, p, area_tolerance_)) t = e;
  });
  return t < 0 ? pressure_outside_mesh(p, nodal_pressure) : hydro::interpolate_pressure(mesh_, nodal_pressure, t, p);
}

// Pseudocode:
//   candidates = the elements whose boxes overlap the segment: the box of a segment near a grid
//                axis, of each of its chunks (about an element long) for an oblique one
//   pieces = the segment clipped to each candidate, sorted by where they start
//   reach = 0
//   for each piece (t0, t1, e) with t1 > reach:
//     a gap (reach, t0) lies outside the mesh: integrate the outside rule's pressure over it
//     integrate e's linear pressure over (max(t0, reach), t1); reach = t1
//   a gap (reach, 1) lies outside the mesh
// A segment along an edge shared by two elements lies in both: the second piece adds nothing
// (the P1 field is the same on the edge from either side).
FacePressureLoads::SegmentIntegrals FacePressureLoads::integrate_along(Point a, Point b,
                                                                      std::span<const double> nodal_pressure) const {
  const double length = geometry::distance(a, b);
  // The lists of the last face this thread integrated, kept for their memory.
  thread_local std::vector<int> candidates;
  thread_local std::vector<SegmentPiece> pieces;
  candidates.clear();
  pieces.clear();
  geometry::Box whole;
  whole.add(a);
  whole.add(b);
  if (std::min(whole.width(), whole.height()) <= 2.0 * chunk_length_) {
    // A face near a grid axis (a bed, a sub-vertical joint): its box is a strip about two
    // elements wide, and one search of it finds each element once.
    elements_->grid().for_each_overlap(whole.inflated(tolerance_), [&](int e) { candidates.push_back(e); });
  } else {
    // An oblique face: boxes of a chunk each, not the one box a diagonal spans.
    const int chunks = std::max(1, static_cast<int>(std::ceil(length / chunk_length_)));
    for (int k = 0; k < chunks; ++k) {
      geometry::Box box;
      box.add(a + (static_cast<double>(k) / chunks) * (b - a));
      box.add(a + (static_cast<double>(k + 1) / chunks) * (b - a));
      elements_->grid().for_each_overlap(box.inflated(tolerance_), [&](int e) { candidates.push_back(e); });
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  }
  for (int e : candidates) {
    const auto& t = mesh_.triangles[e];
    if (const auto part = clip_segment(a, b, mesh_.nodes[t[0]], mesh_.nodes[t[1]], mesh_.nodes[t[2]], tolerance_))
      pieces.push_back({part->first, part->second, e});
  }
  std::sort(pieces.begin(), pieces.end(), [](const SegmentPiece& x, const SegmentPiece& y) {
    return x.t0 != y.t0 ? x.t0 < y.t0 : x.element < y.element;
  });

  // ∫ p dt and ∫ p t dt over [0, 1], piece by piece, inside and outside the mesh: p is linear
  // on each piece, from pa to pb, and
  //   ∫ p dt = (t1 − t0)(pa + pb)/2,   ∫ p t dt = (t1 − t0)(pa (2 t0 + t1) + pb (t0 + 2 t1))/6.
  double integral[2] = {0.0, 0.0}, weighted[2] = {0.0, 0.0};  // [0] inside, [1] outside
  bool outside = false;
  const auto add = [&](int where, double t0, double t1, double pa, double pb) {
    integral[where] += 0.5 * (t1 - t0) * (pa + pb);
    weighted[where] += (t1 - t0) * (pa * (2.0 * t0 + t1) + pb * (t0 + 2.0 * t1)) / 6.0;
  };
  const auto at = [&](double t) { return a + t * (b - a); };
  const auto add_outside = [&](double t0, double t1) {
    outside = true;
    const std::vector<double> cuts = cut_where_nearest_side_changes(at(t0), at(t1));
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double s0 = t0 + cuts[k] * (t1 - t0), s1 = t0 + cuts[k + 1] * (t1 - t0);
      add(1, s0, s1, pressure_outside_mesh(at(s0), nodal_pressure), pressure_outside_mesh(at(s1), nodal_pressure));
    }
  };
  // A gap shorter than the tolerance is round-off between neighbouring elements, not a part
  // outside the mesh: the next element's field covers it.
  const double gap = length > 0.0 ? tolerance_ / length : 0.0;
  double reach = 0.0;
  for (const SegmentPiece& piece : pieces) {
    if (piece.t1 <= reach) continue;
    const bool outside_before = piece.t0 > reach + gap;
    if (outside_before) add_outside(reach, piece.t0);
    const double t0 = outside_before ? piece.t0 : reach;
    add(0, t0, piece.t1, hydro::interpolate_pressure(mesh_, nodal_pressure, piece.element, at(t0)),
        hydro::interpolate_pressure(mesh_, nodal_pressure, piece.element, at(piece.t1)));
    reach = piece.t1;
  }
  if (reach < 1.0 - gap) add_outside(reach, 1.0);
  SegmentIntegrals out;
  out.start_inside = length * (integral[0] - weighted[0]);
  out.end_inside = length * weighted[0];
  out.start_outside = length * (integral[1] - weighted[1]);
  out.end_outside = length * weighted[1];
  out.leaves_mesh = outside;
  return out;
}

std::vector<Point> FacePressureLoads::load_mesh_boundary_across(const geometry::Polygon& block, double alpha,
                                                              std::span<const double> nodal_pressure) const {
  ForceMoments moments;
  moments.origin = vertex_mean(block);
  const geometry::Box box = geometry::bounding_box(block).inflated(tolerance_);
  const std::size_t n = block.size();
  std::vector<double> cuts;
  for (const BoundarySide& side : boundary_) {
    geometry::Box side_box;
    side_box.add(side.a);
    side_box.add(side.b);
    if (!side_box.overlaps(box)) continue;
    // Where the side crosses the block's edges or passes its corners: between two such cuts
    // it lies wholly inside the block or wholly outside.
    cuts.assign({0.0, 1.0});
    const Point along = side.b - side.a;
    const double length_squared = dot(along, along);
    for (std::size_t i = 0; i < n; ++i) {
      const Point c = block[i], d = block[(i + 1) % n];
      if (geometry::segments_intersect(side.a, side.b, c, d))
        if (const auto t = geometry::line_intersection_parameter(side.a, side.b, c, d)) cuts.push_back(*t);
      if (geometry::distance_to_segment(c, side.a, side.b) <= tolerance_) cuts.push_back(dot(c - side.a, along) / length_squared);
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double t0 = std::clamp(cuts[k], 0.0, 1.0), t1 = std::clamp(cuts[k + 1], 0.0, 1.0);
      if (!(t1 > t0)) continue;
      const Point a = side.a + t0 * along, b = side.a + t1 * along, middle = 0.5 * (a + b);
      if (!geometry::contains(block, middle)) continue;
      // A side along one of the block's own faces is not across it.
      double to_boundary = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < n; ++i)
        to_boundary = std::min(to_boundary, geometry::distance_to_segment(middle, block[i], block[(i + 1) % n]));
      if (to_boundary <= tolerance_) continue;
      moments.add_along(a, b, alpha * hydro::interpolate_pressure(mesh_, nodal_pressure, side.triangle, a),
                        alpha * hydro::interpolate_pressure(mesh_, nodal_pressure, side.triangle, b), side.outward);
    }
  }
  return distribute_to_vertices(block, moments);
}

std::vector<std::vector<Point>> FacePressureLoads::compute(std::span<const geometry::Polygon> blocks,
                                                           std::span<const double> nodal_pressure,
                                                           std::span<const double> biot,
                                                           std::span<const std::vector<char>> sealed) const {
  if (nodal_pressure.size() != mesh_.nodes.size())
    throw std::invalid_argument("pressure forces: one pressure per fluid node is needed");
  if (biot.size() != blocks.size())
    throw std::invalid_argument("pressure forces: one Biot coefficient per block is needed");
  std::vector<std::vector<Point>> forces(blocks.size());
  // Each block's loads are its own, so the threads share the blocks in small chunks taken as
  // they finish (the blocks that leave the mesh cost several times the others, and lie
  // together; fixed halves left one thread waiting). A mesh that has no elements, the one
  // failure, is refused before the threads start.
  if (mesh_.triangles.empty() && !blocks.empty()) throw std::invalid_argument("pressure forces: the fluid mesh has no elements");
  const auto load_block = [&](std::size_t b) {
    const geometry::Polygon& poly = blocks[b];
    const std::size_t n = poly.size();
    forces[b].assign(n, Point{});
    // Inside the mesh the faces take 1 − α of the pressure, outside it all of it.
    const double share = 1.0 - biot[b];
    bool leaves_mesh = false;
    const std::vector<char>* sealed_edges = b < sealed.size() && !sealed[b].empty() ? &sealed[b] : nullptr;
    for (std::size_t i = 0; i < n; ++i) {
      if (sealed_edges && (*sealed_edges)[i] != 0) continue;
      const std::size_t j = (i + 1) % n;
      const Point edge = poly[j] - poly[i];
      // The unit inward normal of a counter-clockwise polygon is the edge turned left, over L;
      // integrate_along's integrals carry the L.
      const Point inward = Point{-edge.y, edge.x} / geometry::norm(edge);
      const SegmentIntegrals p = integrate_along(poly[i], poly[j], nodal_pressure);
      forces[b][i] += (share * p.start_inside + p.start_outside) * inward;
      forces[b][j] += (share * p.end_inside + p.end_outside) * inward;
      leaves_mesh = leaves_mesh || p.leaves_mesh;
    }
    if (leaves_mesh && biot[b] > 0.0) {
      const std::vector<Point> across = load_mesh_boundary_across(poly, biot[b], nodal_pressure);
      for (std::size_t v = 0; v < n; ++v) forces[b][v] += across[v];
    }
  };
  const auto count = static_cast<std::ptrdiff_t>(blocks.size());
#pragma omp parallel for schedule(dynamic, 16) if (blocks.size() >= kBlocksWorthTwoThreads) \
    num_threads(numerics::thread_count())
  for (std::ptrdiff_t b = 0; b < count; ++b) load_block(static_cast<std::size_t>(b));
  return forces;
}

}  // namespace hydrodda::coupling
