#pragma once
// A structured triangulation of a rectangle for the coupling tests: nx × ny cells, each split
// into two counter-clockwise triangles (alternating diagonals, so the mesh has no bias).

#include "mesh/triangle_mesh.hpp"

namespace hydrodda::testing {

inline mesh::TriangleMesh make_rectangle_mesh(double x0, double y0, double x1, double y1, int nx, int ny) {
  mesh::TriangleMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.nodes.push_back({x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny});
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  m.region.assign(m.triangles.size(), 0);
  m.region_names = {"domain"};
  return m;
}

}  // namespace hydrodda::testing
