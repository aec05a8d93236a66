#pragma once
// Permeability fixed per named region, for flow-only runs.

#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

struct RegionPermeability {
  std::string region;         // a name in TriangleMesh::region_names
  double permeability = 0.0;  // m²
};

// k per triangle from its region's value. Throws when a region is unknown to the mesh, a
// value is not positive and finite, or some triangle's region has no value (naming it).
std::vector<double> assign_region_permeability(const mesh::TriangleMesh& mesh,
                                               const std::vector<RegionPermeability>& values);

}  // namespace hydrodda::hydro
