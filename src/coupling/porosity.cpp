#include "coupling/porosity.hpp"

#include <algorithm>
#include <stdexcept>

#include "dda/parallel.hpp"

namespace hydrodda::coupling {

namespace {
std::vector<std::array<Point, 3>> gather(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles) {
  std::vector<std::array<Point, 3>> out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) out.push_back({nodes[t[0]], nodes[t[1]], nodes[t[2]]});
  return out;
}

geometry::Box box_of(const std::array<Point, 3>& t) {
  return {{std::min({t[0].x, t[1].x, t[2].x}), std::min({t[0].y, t[1].y, t[2].y})},
          {std::max({t[0].x, t[1].x, t[2].x}), std::max({t[0].y, t[1].y, t[2].y})}};
}
}  // namespace

PorosityMapper::PorosityMapper(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles)
    : triangles_(gather(nodes, triangles)) {
  areas_.reserve(triangles_.size());
  for (const auto& t : triangles_) areas_.push_back(geometry::area(t));
}

double PorosityMapper::compute_covered_area(int e, const geometry::ClipPolygons& blocks,
                                            const geometry::SpatialGrid& grid, Scratch& scratch) const {
  const std::array<Point, 3>& t = triangles_[e];
  const double a = areas_[e];
  // Most elements lie inside one block, often the one that held the element before (mesh
  // order follows space): then A_f = 0 whatever else overlaps, as the sum below would give.
  int& hint = scratch.hint;
  if (hint >= 0 && blocks.holds(hint, t)) return a;
  // The blocks over the element in block order, so that the sum does not depend on the grid.
  std::vector<int>& candidates = scratch.candidates;
  candidates.clear();
  grid.for_each_overlap(box_of(t), [&](int b) {
    candidates.insert(std::upper_bound(candidates.begin(), candidates.end(), b), b);
  });
  double covered = 0.0;
  for (int b : candidates) {
    const double part = blocks.covered_area(b, t, a);
    if (part == a && blocks.holds(b, t)) hint = b;
    covered += part;
    // Covered already: more blocks cannot open it.
    if (covered >= a) break;
  }
  return covered;
}

PorosityField PorosityMapper::compute(std::span<const geometry::Polygon> blocks, double matrix_porosity) const {
  if (!(matrix_porosity >= 0.0 && matrix_porosity < 1.0))
    throw std::invalid_argument("porosity: the matrix porosity must lie in [0, 1)");
  const std::size_t n = triangles_.size();
  // The blocks as they are in this pass: their edges as half-planes, and a grid over their
  // boxes (about one block per cell) to find those over each element.
  const geometry::ClipPolygons prepared(blocks);
  const geometry::SpatialGrid grid(prepared.boxes(), 1.0);
  PorosityField field;
  field.fracture_area.resize(n);
  field.porosity.resize(n);
  // Each element on its own: the halves side by side give the same field as one thread.
  dda::run_two_parts(n >= 20000, [&](int part) {
    const auto [begin, end] = dda::half_range(part, n);
    Scratch scratch;
    for (std::size_t e = begin; e < end; ++e) {
      const double a = areas_[e];
      const double covered = compute_covered_area(static_cast<int>(e), prepared, grid, scratch);
      const double open = std::clamp(a - covered, 0.0, a);
      field.fracture_area[e] = open;
      field.porosity[e] = std::clamp((open / a) * (1.0 - matrix_porosity) + matrix_porosity, matrix_porosity, 1.0);
    }
  });
  return field;
}

}  // namespace hydrodda::coupling
