#include "coupling/element_index.hpp"

#include "geometry/polygon.hpp"

namespace hydrodda::coupling {

namespace {
std::vector<std::array<geometry::Point, 3>> gather(std::span<const geometry::Point> nodes,
                                                   std::span<const std::array<int, 3>> triangles) {
  std::vector<std::array<geometry::Point, 3>> out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) out.push_back({nodes[t[0]], nodes[t[1]], nodes[t[2]]});
  return out;
}

std::vector<geometry::Box> boxes_of(std::span<const std::array<geometry::Point, 3>> corners) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(corners.size());
  for (const auto& t : corners) {
    geometry::Box box;
    for (geometry::Point p : t) box.add(p);
    boxes.push_back(box);
  }
  return boxes;
}
}  // namespace

ElementIndex::ElementIndex(std::span<const geometry::Point> nodes, std::span<const std::array<int, 3>> triangles)
    : corners_(gather(nodes, triangles)), grid_(boxes_of(corners_)) {
  areas_.reserve(corners_.size());
  for (const auto& t : corners_) areas_.push_back(geometry::area(t));
}

}  // namespace hydrodda::coupling
