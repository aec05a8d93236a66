#pragma once
// A uniform grid over bounding boxes: which items may overlap a query box. Built once for a
// fixed set (the fluid mesh's triangles), queried many times (each block, each pass).

#include <algorithm>
#include <span>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::geometry {

class SpatialGrid {
 public:
  // About `items_per_cell` boxes per cell on average; the grid covers the union of the boxes.
  explicit SpatialGrid(std::span<const Box> boxes, double items_per_cell = 2.0);

  // Calls visit(id) once for each item whose box overlaps `query`, in increasing id order
  // within a cell; an item spanning several cells is reported once (deduplicated by a stamp).
  template <class Visit>
  void for_each_overlap(const Box& query, Visit&& visit) const;

  int size() const { return static_cast<int>(boxes_.size()); }

 private:
  std::vector<Box> boxes_;
  Box bounds_;
  int columns_ = 1;
  int rows_ = 1;
  double inverse_width_ = 0.0;
  double inverse_height_ = 0.0;
  std::vector<int> cell_start_;  // CSR: the items of cell c are items_[start[c] .. start[c+1])
  std::vector<int> items_;
  mutable std::vector<unsigned> stamp_;
  mutable unsigned current_stamp_ = 0;

  int column_of(double x) const;
  int row_of(double y) const;
};

template <class Visit>
void SpatialGrid::for_each_overlap(const Box& query, Visit&& visit) const {
  if (boxes_.empty() || !query.overlaps(bounds_)) return;
  if (++current_stamp_ == 0) {  // wrapped: clear the stamps once every 2^32 queries
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    current_stamp_ = 1;
  }
  const int c0 = column_of(query.lo.x), c1 = column_of(query.hi.x);
  const int r0 = row_of(query.lo.y), r1 = row_of(query.hi.y);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      const int cell = r * columns_ + c;
      for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const int id = items_[k];
        if (stamp_[id] == current_stamp_) continue;
        stamp_[id] = current_stamp_;
        if (boxes_[id].overlaps(query)) visit(id);
      }
    }
}

}  // namespace hydrodda::geometry
