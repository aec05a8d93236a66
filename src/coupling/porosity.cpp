#include "coupling/porosity.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "numerics/parallel.hpp"

namespace hydrodda::coupling {

namespace {
// The blocks over a box (an element's) in block order, so that sums do not depend on the grid.
void find_candidates(const geometry::Box& box, const geometry::SpatialGrid& grid, std::vector<int>& candidates) {
  candidates.clear();
  grid.for_each_overlap(box, [&](int b) {
    candidates.insert(std::upper_bound(candidates.begin(), candidates.end(), b), b);
  });
}
}  // namespace

PorosityMapper::PorosityMapper(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles)
    : elements_(std::make_shared<const ElementIndex>(nodes, triangles)) {}

PorosityMapper::PorosityMapper(std::shared_ptr<const ElementIndex> elements) : elements_(std::move(elements)) {}

double PorosityMapper::compute_covered_area(int e, const geometry::ClipPolygons& blocks,
                                            const geometry::SpatialGrid& grid, Scratch& scratch) const {
  const std::array<Point, 3> t = elements_->corners(static_cast<std::size_t>(e));
  const double a = elements_->areas()[e];
  // Most elements lie inside one block, often the one that held the element before (mesh
  // order follows space): then A_f = 0 whatever else overlaps, as the sum below would give.
  int& hint = scratch.hint;
  if (hint >= 0 && blocks.holds(hint, t)) return a;
  std::vector<int>& candidates = scratch.candidates;
  find_candidates(elements_->grid().box(e), grid, candidates);
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

double PorosityMapper::compute_pieces(int e, const geometry::ClipPolygons& blocks, const geometry::SpatialGrid& grid,
                                      Scratch& scratch, std::vector<BlockPiece>& pieces) const {
  const std::array<Point, 3> t = elements_->corners(static_cast<std::size_t>(e));
  const double a = elements_->areas()[e];
  find_candidates(elements_->grid().box(e), grid, scratch.candidates);
  // Every block's part is wanted (the seepage force acts on overlapping blocks too), so no
  // early out; the sum is compute_covered_area's, or A_e or more where that one stopped early,
  // which leaves A_f = 0 either way.
  double covered = 0.0;
  for (int b : scratch.candidates) {
    const geometry::ClippedPart part = blocks.covered_part(b, t, a);
    if (part.area > 0.0) pieces.push_back({b, e, part.area, part.centroid});
    covered += part.area;
  }
  return covered;
}

double equivalent_porosity(double open_area, double element_area, double matrix_porosity) {
  return std::clamp((open_area / element_area) * (1.0 - matrix_porosity) + matrix_porosity, matrix_porosity, 1.0);
}

PorosityField PorosityMapper::compute(std::span<const geometry::Polygon> blocks, double matrix_porosity,
                                      BlockPieces* pieces) const {
  if (!(matrix_porosity >= 0.0 && matrix_porosity < 1.0))
    throw std::invalid_argument("porosity: the matrix porosity must lie in [0, 1)");
  const auto n = static_cast<std::size_t>(elements_->size());
  // The blocks as they are in this pass: their edges as half-planes, and a grid over their
  // boxes (about one block per cell) to find those over each element.
  const geometry::ClipPolygons prepared(blocks);
  const geometry::SpatialGrid grid(prepared.boxes(), 1.0);
  PorosityField field;
  field.fracture_area.resize(n);
  field.porosity.resize(n);
  const std::size_t chunk = BlockPieces::kElementsPerList;
  if (pieces) {
    pieces->lists_.resize(numerics::chunk_count(n, chunk));
    pieces->released_sizes_.resize(pieces->lists_.size());
  }
  // Each element on its own: chunks over the threads give the same field as one thread.
  numerics::for_each_chunk(n >= 20000, n, chunk, [&](std::size_t k, std::size_t begin, std::size_t end) {
    std::vector<BlockPiece>* own = pieces ? &pieces->lists_[k] : nullptr;
    if (own) {
      own->clear();
      // As many as the last clip found, and a few more: no doubling, no copy to make it tight.
      const std::size_t expected = pieces->released_sizes_[k];
      own->reserve(expected + expected / 16);
    }
    Scratch scratch;
    for (std::size_t e = begin; e < end; ++e) {
      const double a = elements_->areas()[e];
      const int element = static_cast<int>(e);
      const double covered = pieces ? compute_pieces(element, prepared, grid, scratch, *own)
                                    : compute_covered_area(element, prepared, grid, scratch);
      const double open = std::clamp(a - covered, 0.0, a);
      field.fracture_area[e] = open;
      field.porosity[e] = equivalent_porosity(open, a, matrix_porosity);
    }
  });
  // A list grown by doubling may hold up to twice its pieces: made tight once (with room for
  // a few more), it is reused so from then on.
  if (pieces)
    for (std::vector<BlockPiece>& list : pieces->lists_)
      if (list.capacity() > list.size() + list.size() / 8) {
        std::vector<BlockPiece> tight;
        tight.reserve(list.size() + list.size() / 16);
        tight.assign(list.begin(), list.end());
        list.swap(tight);
      }
  return field;
}

}  // namespace hydrodda::coupling
