#include "hydro/region_permeability.hpp"

#include <cmath>
#include <stdexcept>

namespace hydrodda::hydro {

std::vector<double> assign_region_permeability(const mesh::TriangleMesh& mesh,
                                               const std::vector<RegionPermeability>& values) {
  std::vector<double> of_region(mesh.region_names.size(), NAN);
  for (const RegionPermeability& v : values) {
    const int r = mesh::find_region(mesh, v.region);
    if (r < 0) throw std::runtime_error("permeability given for region '" + v.region +
                                        "', which the mesh does not have");
    if (!(v.permeability > 0.0) || !std::isfinite(v.permeability))
      throw std::runtime_error("permeability of region '" + v.region + "' must be positive");
    of_region[r] = v.permeability;
  }
  std::vector<double> k(mesh.triangles.size());
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    k[t] = of_region[mesh.region[t]];
    if (std::isnan(k[t]))
      throw std::runtime_error("no permeability for region '" + mesh.region_names[mesh.region[t]] +
                               "' (triangle " + std::to_string(t) + ")");
  }
  return k;
}

}  // namespace hydrodda::hydro
