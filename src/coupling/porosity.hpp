#pragma once
// Equivalent porosity of each fluid element from the blocks that cover it (the paper's eq. 8):
//   φ_e = (A_f / A_e)(1 − φ_m) + φ_m,   A_f = A_e − Σ_blocks |e ∩ block|,
// clamped to [φ_m, 1]: where blocks overlap (contact penetration) the covered area can exceed
// A_e, and A_f is then taken as 0. Parts of blocks outside the fluid mesh count for nothing.

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "coupling/element_index.hpp"
#include "geometry/clipping.hpp"
#include "geometry/point.hpp"
#include "geometry/polygon.hpp"
#include "geometry/spatial_grid.hpp"

namespace hydrodda::coupling {

using geometry::Point;

struct PorosityField {
  std::vector<double> fracture_area;  // A_f per element (m²)
  std::vector<double> porosity;       // φ per element
};

// The paper's eq. 8 for one element: (open / area)(1 − φ_m) + φ_m, clamped to [φ_m, 1].
double equivalent_porosity(double open_area, double element_area, double matrix_porosity);

// The part of a block over one fluid element, as the clip found it: the seepage force is
// integrated over these (seepage_forces.hpp).
struct BlockPiece {
  int block = 0;
  int element = 0;
  double area = 0.0;  // m²
  Point centroid;
};

// Every block ∩ element part a clip found, in element order: a list for each chunk of
// kElementsPerList elements, the chunks in order. Each list is filled by the thread that clips
// its chunk and kept where it was made: joined into one they would be copied once more (at a
// million triangles some 40 MB).
class BlockPieces {
 public:
  static constexpr std::size_t kElementsPerList = 4096;
  std::size_t size() const {
    std::size_t n = 0;
    for (const auto& list : lists_) n += list.size();
    return n;
  }
  // The pieces over each chunk of the elements, the chunks in order.
  const std::vector<std::vector<BlockPiece>>& lists() const { return lists_; }
  // Lets go of the lists and their storage (76 MB at 10^6 triangles and 10^4 blocks): a
  // coupled pass needs them from the clip to the seepage force only, not while the blocks move.
  void release() {
    released_sizes_.resize(lists_.size());
    for (std::size_t k = 0; k < lists_.size(); ++k) released_sizes_[k] = lists_[k].size();
    lists_ = {};
  }

 private:
  friend class PorosityMapper;
  std::vector<std::vector<BlockPiece>> lists_;
  std::vector<std::size_t> released_sizes_;  // how many each list held when let go
};

// Keeps an index of the fixed mesh's elements (an ElementIndex, shared or its own, with views
// of `nodes` and `triangles`, which must outlive the mapper); each pass clips every element
// against the blocks as they are then.
class PorosityMapper {
 public:
  PorosityMapper(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles);
  explicit PorosityMapper(std::shared_ptr<const ElementIndex> elements);

  // Blocks: simple polygons in either orientation. matrix_porosity in [0, 1). With `pieces`
  // (replaced; its storage reused when it has any), also every block ∩ element part of non-zero area, from
  // the same clips, in element order (whatever the threads: a sum over a block's pieces in
  // this order is the same on any number of threads); the field is then the same, bit for bit.
  PorosityField compute(std::span<const geometry::Polygon> blocks, double matrix_porosity,
                        BlockPieces* pieces = nullptr) const;

  const std::vector<double>& element_areas() const { return elements_->areas(); }

 private:
  // What one thread keeps from element to element.
  struct Scratch {
    int hint = -1;                // the last block that held a whole element: tried first
    std::vector<int> candidates;  // the blocks over the element
  };
  // Σ_blocks |e ∩ block| for element e, or A_e as soon as one block holds the whole element.
  double compute_covered_area(int e, const geometry::ClipPolygons& blocks, const geometry::SpatialGrid& grid,
                              Scratch& scratch) const;
  // The same sum over every block over element e, without early outs, each part of non-zero
  // area appended to `pieces`.
  double compute_pieces(int e, const geometry::ClipPolygons& blocks, const geometry::SpatialGrid& grid,
                        Scratch& scratch, std::vector<BlockPiece>& pieces) const;

  std::shared_ptr<const ElementIndex> elements_;
};

}  // namespace hydrodda::coupling
