#pragma once
// Fluid pressure to block vertex forces (the paper's §3.3). Each block vertex takes the pressure
// of the fluid element that contains it (pressure at that element's centroid); along an edge
// 1–2 of length L the pressure, linear between p1 and p2, is lumped to its ends as the
// consistent loads
//   F1 = L (2 p1 + p2) / 6,   F2 = L (p1 + 2 p2) / 6,
// along the edge's inward normal. A uniform pressure then gives no net force or moment, and a
// linear (hydrostatic) one gives Archimedes' buoyancy exactly.

#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"
#include "mesh/point_locator.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::coupling {

using geometry::Point;

// The consistent edge loads of a pressure field sampled at each vertex (blocks
// counter-clockwise): forces[b][v] for vertex v of block b.
std::vector<std::vector<Point>> compute_edge_load_forces(std::span<const geometry::Polygon> blocks,
                                                         std::span<const std::vector<double>> vertex_pressure);

// Samples the element pressures at block vertices through the mesh's point locator; a vertex
// outside the mesh (a block moved partly out of the fluid domain) takes the pressure of the
// element whose boundary edge is nearest to it, the element the mesh meets closest.
class VertexPressureSampler {
 public:
  explicit VertexPressureSampler(const mesh::TriangleMesh& mesh);
  std::vector<std::vector<double>> sample(std::span<const geometry::Polygon> blocks,
                                          std::span<const double> element_pressure) const;

 private:
  const mesh::TriangleMesh& mesh_;
  mesh::PointLocator locator_;
  struct BoundarySide {
    Point a, b;
    int triangle;
  };
  std::vector<BoundarySide> boundary_;  // the mesh boundary's edges with their triangle
  int find_nearest_boundary_element(Point p) const;
};

}  // namespace hydrodda::coupling
