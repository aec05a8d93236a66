#pragma once
// No surprise meshes: the triangles a scenario's [mesh] sizes will give, estimated before
// Gmsh is asked (mesh/mesh_estimate.hpp), set against what this machine can hold and mesh in
// reasonable time. Measured on the 10^6-triangle seal (docs/performance.md): a coupled run
// peaks at about 1,200 bytes a triangle, and Gmsh meshes about 54,000 triangles a second on
// one core.

#include <string>

#include "mesh/mesh_request.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// "about 1.08 million triangles (…)": the estimate, with its parts near the fractures and
// elsewhere. Logs a warning when meshing would take over a minute or the run would need over
// half the machine's memory; throws scenario::ScenarioError naming mesh.size,
// mesh.fracture_size and mesh.refine_distance when it would need more memory than the machine
// has.
std::string check_mesh_budget(const scenario::Scenario& scenario, const mesh::MeshRequest& request);

}  // namespace hydrodda::run
