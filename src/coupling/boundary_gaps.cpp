#include "coupling/boundary_gaps.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "coupling/local_aperture.hpp"
#include "geometry/clipping.hpp"

namespace hydrodda::coupling {

BoundaryGaps::BoundaryGaps(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles,
                           const geometry::Polygon& domain, std::span<const geometry::Polygon> blocks_as_built)
    : BoundaryGaps(std::make_shared<const ElementIndex>(nodes, triangles), domain, blocks_as_built) {}

BoundaryGaps::BoundaryGaps(std::shared_ptr<const ElementIndex> elements, const geometry::Polygon& domain,
                           std::span<const geometry::Polygon> blocks_as_built)
    : elements_(std::move(elements)), domain_(domain) {
  const int n = static_cast<int>(domain.size());
  if (n == 0) return;  // no domain given (a loop built by hand): no face is followed
  if (n < 3) throw std::invalid_argument("boundary gaps: the domain needs at least three vertices");
  const double orientation = geometry::signed_area(domain) > 0.0 ? 1.0 : -1.0;
  const geometry::Box box = geometry::bounding_box(domain);
  const double tolerance = 1e-9 * std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
  for (int i = 0; i < n; ++i) {
    const Point a = domain[i], b = domain[(i + 1) % n];
    const Point t = (b - a) / geometry::norm(b - a);
    sides_.push_back({a, b, orientation * Point{-t.y, t.x}});  // left of a→b for a CCW domain
  }
  auto side_holding = [&](Point p, Point q) {
    for (int s = 0; s < n; ++s)
      if (geometry::distance_to_segment(p, sides_[s].a, sides_[s].b) <= tolerance &&
          geometry::distance_to_segment(q, sides_[s].a, sides_[s].b) <= tolerance)
        return s;
    return -1;
  };
  for (int b = 0; b < static_cast<int>(blocks_as_built.size()); ++b) {
    const geometry::Polygon& block = blocks_as_built[b];
    const int m = static_cast<int>(block.size());
    std::vector<int> side_of_face(m);
    for (int v = 0; v < m; ++v) {
      side_of_face[v] = side_holding(block[v], block[(v + 1) % m]);
      if (side_of_face[v] >= 0) faces_.push_back({b, v, side_of_face[v]});
    }
    // A vertex between faces on two adjacent sides lay on their common corner.
    for (int v = 0; v < m; ++v) {
      const int before = side_of_face[(v + m - 1) % m], after = side_of_face[v];
      if (before < 0 || after < 0 || before == after) continue;
      if ((before + 1) % n == after) corners_.push_back({b, v, before, after, domain[after]});
      else if ((after + 1) % n == before) corners_.push_back({b, v, before, after, domain[before]});
    }
  }
  // Mouths: a boundary face ending where a face of another block on the same side starts.
  for (const BoundaryFace& before : faces_) {
    const geometry::Polygon& pb = blocks_as_built[before.block];
    const Point start = pb[before.vertex], end = pb[(before.vertex + 1) % pb.size()];
    for (const BoundaryFace& after : faces_) {
      if (after.block == before.block || after.side != before.side) continue;
      if (geometry::distance(blocks_as_built[after.block][after.vertex], end) > tolerance) continue;
      mouths_.push_back({before.block, (before.vertex + 1) % static_cast<int>(pb.size()), after.block, after.vertex,
                         before.side, (end - start) / geometry::norm(end - start)});
    }
  }
}

std::vector<geometry::Polygon> BoundaryGaps::find_gaps(std::span<const geometry::Polygon> blocks) const {
  std::vector<geometry::Polygon> gaps;
  for (const BoundaryFace& f : faces_) {
    const geometry::Polygon& block = blocks[f.block];
    const Side& side = sides_[f.side];
    Point a = block[f.vertex], b = block[(f.vertex + 1) % block.size()];
    double da = geometry::dot(a - side.a, side.inward), db = geometry::dot(b - side.a, side.inward);
    if (da <= 0.0 && db <= 0.0) continue;  // on the boundary or outside the domain
    // A face that crosses the boundary line: only its part inside leaves a gap.
    if (da < 0.0) a = a + (da / (da - db)) * (b - a), da = 0.0;
    if (db < 0.0) b = a + (da / (da - db)) * (b - a), db = 0.0;
    gaps.push_back({a, b, b - db * side.inward, a - da * side.inward});
  }
  for (const Corner& c : corners_) {
    const Point v = blocks[c.block][c.vertex];
    const Side &before = sides_[c.side_before], &after = sides_[c.side_after];
    const double d_before = geometry::dot(v - before.a, before.inward);
    const double d_after = geometry::dot(v - after.a, after.inward);
    if (d_before <= 0.0 || d_after <= 0.0) continue;
    gaps.push_back({v, v - d_before * before.inward, c.corner, v - d_after * after.inward});
  }
  for (const Mouth& m : mouths_) {
    const Point p = blocks[m.block_before][m.vertex_before], q = blocks[m.block_after][m.vertex_after];
    const Side& side = sides_[m.side];
    const double dp = geometry::dot(p - side.a, side.inward), dq = geometry::dot(q - side.a, side.inward);
    // Ends that overlap along the side leave no sliver: their strips meet or cross.
    if (dp <= 0.0 || dq <= 0.0 || geometry::dot(q - p, m.along) <= 0.0) continue;
    gaps.push_back({p, q, q - dq * side.inward, p - dp * side.inward});
  }
  return gaps;
}

std::vector<double> BoundaryGaps::compute_gap_areas(std::span<const geometry::Polygon> blocks) const {
  std::vector<double> areas(static_cast<std::size_t>(elements_->size()), 0.0);
  for (const geometry::Polygon& gap : find_gaps(blocks)) {
    if (geometry::area(gap) == 0.0) continue;
    elements_->grid().for_each_overlap(geometry::bounding_box(gap), [&](int e) {
      areas[e] += geometry::clipped_area(elements_->corners(static_cast<std::size_t>(e)), gap);
    });
  }
  return areas;
}

MeshExcursion BoundaryGaps::find_excursion(std::span<const geometry::Polygon> blocks) const {
  MeshExcursion out;
  if (domain_.empty()) return out;
  for (int b = 0; b < static_cast<int>(blocks.size()); ++b) {
    bool outside = false;
    for (Point v : blocks[b]) {
      const double d = signed_distance(v, domain_);  // > 0 outside
      if (d <= 0.0) continue;
      outside = true;
      if (d > out.distance) out.distance = d, out.block = b;
    }
    out.blocks_outside += outside ? 1 : 0;
  }
  return out;
}

void exclude_boundary_gaps(PorosityField& field, std::span<const double> gap_area,
                           std::span<const double> element_areas, double matrix_porosity) {
  if (gap_area.size() != field.fracture_area.size() || element_areas.size() != gap_area.size())
    throw std::invalid_argument("boundary gaps: one gap area and one element area per element are needed");
  for (std::size_t e = 0; e < gap_area.size(); ++e) {
    if (gap_area[e] <= 0.0) continue;
    const double open = std::max(field.fracture_area[e] - gap_area[e], 0.0);
    field.fracture_area[e] = open;
    field.porosity[e] = equivalent_porosity(open, element_areas[e], matrix_porosity);
  }
}

}  // namespace hydrodda::coupling
