#include "coupling/element_index.hpp"

#include "geometry/polygon.hpp"

namespace hydrodda::coupling {

namespace {
std::vector<geometry::Box> boxes_of(const ElementIndex& elements) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(static_cast<std::size_t>(elements.size()));
  for (std::size_t e = 0; e < static_cast<std::size_t>(elements.size()); ++e) {
    geometry::Box box;
    for (geometry::Point p : elements.corners(e)) box.add(p);
    boxes.push_back(box);
  }
  return boxes;
}
}  // namespace

ElementIndex::ElementIndex(std::span<const geometry::Point> nodes, std::span<const std::array<int, 3>> triangles)
    : nodes_(nodes), triangles_(triangles), grid_(boxes_of(*this)) {
  areas_.reserve(triangles.size());
  for (std::size_t e = 0; e < triangles.size(); ++e) areas_.push_back(geometry::area(corners(e)));
}

}  // namespace hydrodda::coupling
