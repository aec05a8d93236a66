#pragma once
// Meshes shared by the flow tests.

#include <cmath>
#include <numbers>

#include "mesh/mesh_request.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro::testing {

// An unstructured Gmsh mesh of the rectangle [0, lx] × [0, ly], refined along a slanted line
// so that it is far from structured.
inline mesh::TriangleMesh make_rectangle_mesh(double lx, double ly, double size) {
  mesh::MeshRequest request;
  request.domain = {{0, 0}, {lx, 0}, {lx, ly}, {0, ly}};
  request.size = size;
  request.fracture_size = size / 4;
  request.refine_distance = 3 * size;
  request.refinement_lines = {{{0.1 * lx, 0.2 * ly}, {0.8 * lx, 0.9 * ly}}};
  return mesh::generate_mesh(request);
}

// A structured annulus r1 ≤ r ≤ r2: nr rings spaced geometrically (so that elements keep
// their shape near the inner circle), nt sectors; every node lies on its circle. Boundaries
// "inner" and "outer".
inline mesh::TriangleMesh make_annulus_mesh(double r1, double r2, int nr, int nt) {
  mesh::TriangleMesh m;
  m.region_names = {"domain"};
  m.boundary_names = {"inner", "outer"};
  for (int i = 0; i <= nr; ++i) {
    const double r = r1 * std::pow(r2 / r1, static_cast<double>(i) / nr);
    for (int j = 0; j < nt; ++j) {
      const double a = 2 * std::numbers::pi * j / nt;
      m.nodes.push_back({r * std::cos(a), r * std::sin(a)});
    }
  }
  auto id = [nt](int i, int j) { return i * nt + (j % nt); };
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nt; ++j) {
      // Alternate the diagonal so that the mesh has no preferred direction.
      if ((i + j) % 2 == 0) {
        m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      } else {
        m.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        m.triangles.push_back({id(i, j + 1), id(i + 1, j), id(i + 1, j + 1)});
      }
      m.region.push_back(0);
      m.region.push_back(0);
    }
  for (int j = 0; j < nt; ++j) {
    m.boundary_edges.push_back({{id(0, j + 1), id(0, j)}, 0});
    m.boundary_edges.push_back({{id(nr, j), id(nr, j + 1)}, 1});
  }
  return m;
}

}  // namespace hydrodda::hydro::testing
