#pragma once
// Structured triangulations for the coupling tests: a grid of cells, each split into two
// counter-clockwise triangles (alternating diagonals, so the mesh has no bias).

#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace hydrodda::testing {

// A tensor-product triangulation: nodes at every (xs[i], ys[j]) (both increasing).
inline mesh::TriangleMesh make_grid_mesh(const std::vector<double>& xs, const std::vector<double>& ys) {
  mesh::TriangleMesh m;
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  for (double y : ys)
    for (double x : xs) m.nodes.push_back({x, y});
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

inline mesh::TriangleMesh make_rectangle_mesh(double x0, double y0, double x1, double y1, int nx, int ny) {
  std::vector<double> xs, ys;
  for (int i = 0; i <= nx; ++i) xs.push_back(x0 + (x1 - x0) * i / nx);
  for (int j = 0; j <= ny; ++j) ys.push_back(y0 + (y1 - y0) * j / ny);
  return make_grid_mesh(xs, ys);
}

}  // namespace hydrodda::testing
