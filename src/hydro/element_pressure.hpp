#pragma once
// Fluid pressure per triangle, as the coupling reads it.

#include <vector>

#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

// Pressure at each triangle's centroid: the mean of its three nodal pressures (exact for P1).
std::vector<double> compute_centroid_pressure(const mesh::TriangleMesh& mesh,
                                              const FlowSolution& solution);

}  // namespace hydrodda::hydro
