#include "hydro/element_pressure.hpp"

namespace hydrodda::hydro {

std::vector<double> compute_centroid_pressure(const mesh::TriangleMesh& mesh,
                                              const FlowSolution& solution) {
  std::vector<double> p(mesh.triangles.size());
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const auto& [a, b, c] = mesh.triangles[t];
    p[t] = (solution.pressure[a] + solution.pressure[b] + solution.pressure[c]) / 3.0;
  }
  return p;
}

}  // namespace hydrodda::hydro
