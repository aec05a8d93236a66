#pragma once
// A uniform grid over bounding boxes: which items may overlap a query box. Built once for a
// set of boxes (the blocks of one coupling pass), queried many times (each fluid element).
// Queries keep no state, so several threads may query one grid at once.

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::geometry {

class SpatialGrid {
 public:
  // About `items_per_cell` boxes per cell on average; the grid covers the union of the boxes.
  explicit SpatialGrid(std::span<const Box> boxes, double items_per_cell = 2.0);

  // Calls visit(id) once for each item whose box overlaps `query`, in increasing id order
  // within a cell, the cells row by row. An item in several of the cells the query covers is
  // reported in the first of them, the cell holding the lower-left corner of the two boxes'
  // overlap: the same order as a visit that skipped every id already seen.
  template <class Visit>
  void for_each_overlap(const Box& query, Visit&& visit) const;

  // The item nearest to p by `distance(id)` (+infinity for an item that does not qualify),
  // the lowest id on a tie; −1 when none qualifies. `distance(id)` must be at least the
  // distance from p to the item's box. Searches squares about p of half-side `first_reach`,
  // doubled until the nearest found lies within the square (every item outside it is farther)
  // or the square covers every box.
  template <class Distance>
  int nearest(Point p, double first_reach, Distance&& distance) const;

  int size() const { return static_cast<int>(boxes_.size()); }
  const Box& box(int id) const { return boxes_[static_cast<std::size_t>(id)]; }

 private:
  std::vector<Box> boxes_;
  Box bounds_;
  int columns_ = 1;
  int rows_ = 1;
  double inverse_width_ = 0.0;
  double inverse_height_ = 0.0;
  std::vector<int> cell_start_;  // CSR: the items of cell c are items_[start[c] .. start[c+1])
  std::vector<int> items_;

  int column_of(double x) const {
    return std::clamp(static_cast<int>((x - bounds_.lo.x) * inverse_width_), 0, columns_ - 1);
  }
  int row_of(double y) const {
    return std::clamp(static_cast<int>((y - bounds_.lo.y) * inverse_height_), 0, rows_ - 1);
  }
};

template <class Visit>
void SpatialGrid::for_each_overlap(const Box& query, Visit&& visit) const {
  if (boxes_.empty() || !query.overlaps(bounds_)) return;
  const int c0 = column_of(query.lo.x), c1 = column_of(query.hi.x);
  const int r0 = row_of(query.lo.y), r1 = row_of(query.hi.y);
  const bool one_cell = c0 == c1 && r0 == r1;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      const int cell = r * columns_ + c;
      for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const int id = items_[k];
        const Box& box = boxes_[id];
        if (!box.overlaps(query)) continue;
        if (one_cell || (std::max(c0, column_of(box.lo.x)) == c && std::max(r0, row_of(box.lo.y)) == r)) visit(id);
      }
    }
}

template <class Distance>
int SpatialGrid::nearest(Point p, double first_reach, Distance&& distance) const {
  if (boxes_.empty()) return -1;
  double reach = first_reach > 0.0 ? first_reach : std::max({bounds_.width(), bounds_.height(), 1e-300});
  for (;; reach *= 2.0) {
    const Box square{{p.x - reach, p.y - reach}, {p.x + reach, p.y + reach}};
    int best = -1;
    double best_distance = INFINITY;
    for_each_overlap(square, [&](int id) {
      const double d = distance(id);
      if (d < best_distance || (d == best_distance && d < INFINITY && id < best)) {
        best_distance = d;
        best = id;
      }
    });
    const bool covers_all = square.lo.x <= bounds_.lo.x && square.lo.y <= bounds_.lo.y &&
                            square.hi.x >= bounds_.hi.x && square.hi.y >= bounds_.hi.y;
    if (best_distance <= reach || covers_all) return best;
  }
}

}  // namespace hydrodda::geometry
