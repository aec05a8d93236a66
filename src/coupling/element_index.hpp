#pragma once
// The fixed fluid mesh's elements as the coupling queries them every pass: each element's
// corners and area, and a grid over their bounding boxes (about two elements a cell). Built
// once per mesh and shared by the porosity clip, the boundary gaps and the face loads: at a
// million triangles it is about 75 MB. The corners are read from the mesh when asked for
// (a copy of them would be 48 MB more).

#include <array>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/spatial_grid.hpp"

namespace hydrodda::coupling {

class ElementIndex {
 public:
  // Keeps views of `nodes` and `triangles`, which must outlive the index.
  ElementIndex(std::span<const geometry::Point> nodes, std::span<const std::array<int, 3>> triangles);

  int size() const { return static_cast<int>(triangles_.size()); }
  std::array<geometry::Point, 3> corners(std::size_t e) const {
    const std::array<int, 3>& t = triangles_[e];
    return {nodes_[static_cast<std::size_t>(t[0])], nodes_[static_cast<std::size_t>(t[1])],
            nodes_[static_cast<std::size_t>(t[2])]};
  }
  const std::vector<double>& areas() const { return areas_; }
  // Over the elements' bounding boxes (grid().box(e) is element e's); ids are element indices.
  const geometry::SpatialGrid& grid() const { return grid_; }

 private:
  std::span<const geometry::Point> nodes_;
  std::span<const std::array<int, 3>> triangles_;
  std::vector<double> areas_;
  geometry::SpatialGrid grid_;
};

}  // namespace hydrodda::coupling
