#pragma once
// Which triangle of a mesh contains a point: a uniform grid over the triangles' bounding
// boxes, built once per mesh (the mesh never changes during a run).

#include <array>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::mesh {

// Whether p lies inside (or on) the counter-clockwise triangle a, b, c: left of all three
// edges, to `area_tolerance` in orient()'s unit. The locator's rule, for others that find
// triangles their own way.
inline bool triangle_holds(Point a, Point b, Point c, Point p, double area_tolerance) {
  return geometry::orient(a, b, p) >= -area_tolerance && geometry::orient(b, c, p) >= -area_tolerance &&
         geometry::orient(c, a, p) >= -area_tolerance;
}

// The locator's area tolerance for a mesh whose nodes span `extent`: 1e-12 of its size, squared.
inline double locator_area_tolerance(double extent) { return 1e-12 * extent * extent; }

class PointLocator {
 public:
  // Keeps a reference to the mesh's nodes and triangles: the mesh must outlive the locator.
  explicit PointLocator(const TriangleMesh& mesh);

  // A triangle containing p (on a shared edge or vertex, the lowest-numbered such triangle),
  // or -1 when p lies outside the mesh by more than a relative 1e-12 of the mesh size.
  int locate(Point p) const;

 private:
  const TriangleMesh& mesh_;
  geometry::Box box_;
  double inverse_cell_ = 1.0;
  int columns_ = 1;
  int rows_ = 1;
  double tolerance_ = 0.0;         // area tolerance for "on an edge", in the orient() unit
  std::vector<int> cell_start_;    // CSR: triangles of cell c are cell_triangles_[start[c]..]
  std::vector<int> cell_triangles_;
};

}  // namespace hydrodda::mesh
