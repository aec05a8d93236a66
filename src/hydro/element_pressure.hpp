#pragma once
// Fluid pressure on the triangles, as the coupling reads it: the P1 field of the nodal
// pressures, linear inside each triangle.

#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

// Pressure at each triangle's centroid: the mean of its three nodal pressures (exact for P1).
std::vector<double> compute_centroid_pressure(const mesh::TriangleMesh& mesh,
                                              const FlowSolution& solution);

// ∇p of each triangle, Σ_i p_i ∇φ_i: constant over the triangle.
std::vector<geometry::Point> compute_pressure_gradients(const mesh::TriangleMesh& mesh,
                                                        std::span<const double> nodal_pressure);

// The P1 pressure of triangle t at p, Σ_i p_i φ_i(p); outside the triangle, the linear
// extension of its field.
double interpolate_pressure(const mesh::TriangleMesh& mesh, std::span<const double> nodal_pressure, int t,
                            geometry::Point p);

}  // namespace hydrodda::hydro
