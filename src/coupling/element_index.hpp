#pragma once
// The fixed fluid mesh's elements as the coupling queries them every pass: each element's
// corners and area, and a grid over their bounding boxes (about two elements a cell). Built
// once per mesh and shared by the porosity clip, the boundary gaps and the face loads: at a
// million triangles each copy of it is about 100 MB.

#include <array>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/spatial_grid.hpp"

namespace hydrodda::coupling {

class ElementIndex {
 public:
  ElementIndex(std::span<const geometry::Point> nodes, std::span<const std::array<int, 3>> triangles);

  int size() const { return static_cast<int>(corners_.size()); }
  const std::vector<std::array<geometry::Point, 3>>& corners() const { return corners_; }
  const std::vector<double>& areas() const { return areas_; }
  // Over the elements' bounding boxes (grid().box(e) is element e's); ids are element indices.
  const geometry::SpatialGrid& grid() const { return grid_; }

 private:
  std::vector<std::array<geometry::Point, 3>> corners_;
  std::vector<double> areas_;
  geometry::SpatialGrid grid_;
};

}  // namespace hydrodda::coupling
