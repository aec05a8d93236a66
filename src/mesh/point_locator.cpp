#include "mesh/point_locator.hpp"

#include <algorithm>
#include <cmath>

namespace hydrodda::mesh {

// Hand-written: a uniform grid beats a tree here because P1 meshes are graded smoothly, and
// the grid's two passes (count, fill) give a compact CSR layout with no allocation per cell.
PointLocator::PointLocator(const TriangleMesh& mesh) : mesh_(mesh) {
  for (const Point& p : mesh.nodes) box_.add(p);
  const int n = mesh.triangle_count();
  if (n == 0) {
    cell_start_.assign(2, 0);
    return;
  }
  // One cell per triangle on average: graded meshes crowd many small triangles into the
  // cells near fractures, so a grid finer than the mean triangle pays (bench_mesh).
  const double cell = std::sqrt(std::max(box_.width() * box_.height(), 1e-300) / (1.0 * n));
  const double extent = std::max(box_.width(), box_.height());
  columns_ = std::clamp(static_cast<int>(box_.width() / cell) + 1, 1, 1 << 14);
  rows_ = std::clamp(static_cast<int>(box_.height() / cell) + 1, 1, 1 << 14);
  inverse_cell_ = 1.0 / std::max(cell, 1e-300 + extent / (1 << 14));
  tolerance_ = locator_area_tolerance(extent);

  auto cell_range = [&](int t) {
    geometry::Box b;
    for (int v : mesh.triangles[t]) b.add(mesh.nodes[v]);
    const int x0 = std::clamp(static_cast<int>((b.lo.x - box_.lo.x) * inverse_cell_), 0, columns_ - 1);
    const int x1 = std::clamp(static_cast<int>((b.hi.x - box_.lo.x) * inverse_cell_), 0, columns_ - 1);
    const int y0 = std::clamp(static_cast<int>((b.lo.y - box_.lo.y) * inverse_cell_), 0, rows_ - 1);
    const int y1 = std::clamp(static_cast<int>((b.hi.y - box_.lo.y) * inverse_cell_), 0, rows_ - 1);
    return std::array<int, 4>{x0, x1, y0, y1};
  };
  cell_start_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (int t = 0; t < n; ++t) {
    const auto [x0, x1, y0, y1] = cell_range(t);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) ++cell_start_[static_cast<std::size_t>(y) * columns_ + x + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_triangles_.resize(cell_start_.back());
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (int t = 0; t < n; ++t) {  // ascending t: each cell's list is sorted
    const auto [x0, x1, y0, y1] = cell_range(t);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cell_triangles_[fill[static_cast<std::size_t>(y) * columns_ + x]++] = t;
  }
}

int PointLocator::locate(Point p) const {
  const double slack = std::sqrt(tolerance_);
  if (p.x < box_.lo.x - slack || p.x > box_.hi.x + slack || p.y < box_.lo.y - slack ||
      p.y > box_.hi.y + slack || cell_triangles_.empty())
    return -1;
  const int x = std::clamp(static_cast<int>((p.x - box_.lo.x) * inverse_cell_), 0, columns_ - 1);
  const int y = std::clamp(static_cast<int>((p.y - box_.lo.y) * inverse_cell_), 0, rows_ - 1);
  const std::size_t c = static_cast<std::size_t>(y) * columns_ + x;
  for (int i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
    const int t = cell_triangles_[i];
    const auto& [a, b, d] = mesh_.triangles[t];
    const Point pa = mesh_.nodes[a], pb = mesh_.nodes[b], pd = mesh_.nodes[d];
    if (triangle_holds(pa, pb, pd, p, tolerance_)) return t;
  }
  return -1;
}

}  // namespace hydrodda::mesh
