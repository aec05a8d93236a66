#include "coupling/porosity.hpp"

#include <algorithm>
#include <stdexcept>

#include "geometry/clipping.hpp"

namespace hydrodda::coupling {

namespace {
std::vector<std::array<Point, 3>> gather(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles) {
  std::vector<std::array<Point, 3>> out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) out.push_back({nodes[t[0]], nodes[t[1]], nodes[t[2]]});
  return out;
}

std::vector<geometry::Box> boxes_of(const std::vector<std::array<Point, 3>>& triangles) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(triangles.size());
  for (const auto& t : triangles) boxes.push_back(geometry::bounding_box(t));
  return boxes;
}
}  // namespace

PorosityMapper::PorosityMapper(std::span<const Point> nodes, std::span<const std::array<int, 3>> triangles)
    : triangles_(gather(nodes, triangles)), grid_(boxes_of(triangles_)) {
  areas_.reserve(triangles_.size());
  for (const auto& t : triangles_) areas_.push_back(geometry::area(t));
}

PorosityField PorosityMapper::compute(std::span<const geometry::Polygon> blocks, double matrix_porosity) const {
  if (!(matrix_porosity >= 0.0 && matrix_porosity < 1.0))
    throw std::invalid_argument("porosity: the matrix porosity must lie in [0, 1)");
  const std::size_t n = triangles_.size();
  std::vector<double> covered(n, 0.0);
  // Block by block: each block's box selects the few elements it can cover.
  for (const geometry::Polygon& block : blocks) {
    const geometry::Box box = geometry::bounding_box(block);
    grid_.for_each_overlap(box, [&](int e) {
      const double a = areas_[e];
      // Early out: an element already fully covered needs no more clipping.
      if (covered[e] >= a) return;
      covered[e] += geometry::clipped_area(triangles_[e], block);
    });
  }
  PorosityField field;
  field.fracture_area.resize(n);
  field.porosity.resize(n);
  for (std::size_t e = 0; e < n; ++e) {
    const double a = areas_[e];
    const double open = std::clamp(a - covered[e], 0.0, a);
    field.fracture_area[e] = open;
    field.porosity[e] = std::clamp((open / a) * (1.0 - matrix_porosity) + matrix_porosity, matrix_porosity, 1.0);
  }
  return field;
}

}  // namespace hydrodda::coupling
