#include "geometry/spatial_grid.hpp"

#include <algorithm>
#include <cmath>

namespace hydrodda::geometry {

SpatialGrid::SpatialGrid(std::span<const Box> boxes, double items_per_cell)
    : boxes_(boxes.begin(), boxes.end()) {
  for (const Box& b : boxes_) {
    bounds_.add(b.lo);
    bounds_.add(b.hi);
  }
  if (boxes_.empty()) return;
  const double width = std::max(bounds_.width(), 1e-300);
  const double height = std::max(bounds_.height(), 1e-300);
  const double cells = std::max(1.0, static_cast<double>(boxes_.size()) / items_per_cell);
  // Square cells: columns / rows follows the aspect ratio.
  columns_ = std::clamp(static_cast<int>(std::sqrt(cells * width / height)), 1, 1 << 14);
  rows_ = std::clamp(static_cast<int>(cells / columns_), 1, 1 << 14);
  inverse_width_ = columns_ / width;
  inverse_height_ = rows_ / height;

  // Counting sort of (cell, item) pairs into CSR arrays.
  cell_start_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  const auto each_cell = [&](const Box& b, auto&& f) {
    for (int r = row_of(b.lo.y); r <= row_of(b.hi.y); ++r)
      for (int c = column_of(b.lo.x); c <= column_of(b.hi.x); ++c) f(r * columns_ + c);
  };
  for (const Box& b : boxes_) each_cell(b, [&](int cell) { ++cell_start_[cell + 1]; });
  for (std::size_t i = 1; i < cell_start_.size(); ++i) cell_start_[i] += cell_start_[i - 1];
  items_.resize(cell_start_.back());
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (int id = 0; id < static_cast<int>(boxes_.size()); ++id)
    each_cell(boxes_[id], [&](int cell) { items_[fill[cell]++] = id; });
}

}  // namespace hydrodda::geometry
