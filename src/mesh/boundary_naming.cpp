#include <algorithm>
#include <cmath>

#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {

void name_boundary_edges(TriangleMesh& mesh, const std::vector<NamedSegment>& segments,
                         const geometry::Box& box) {
  const double tolerance = 1e-9 * std::max(box.width(), box.height());
  mesh.boundary_names.clear();
  for (const NamedSegment& s : segments) mesh.boundary_names.push_back(s.name);
  for (const std::string& name : kDefaultBoundaryNames) mesh.boundary_names.push_back(name);
  const int first_default = static_cast<int>(segments.size());

  auto on_segment = [&](Point p, Point a, Point b) {
    return geometry::distance_to_segment(p, a, b) <= tolerance;
  };
  auto name_of = [&](Point p, Point q) {
    for (std::size_t s = 0; s < segments.size(); ++s)
      if (on_segment(p, segments[s].from, segments[s].to) &&
          on_segment(q, segments[s].from, segments[s].to))
        return static_cast<int>(s);
    if (std::abs(p.x - box.lo.x) <= tolerance && std::abs(q.x - box.lo.x) <= tolerance)
      return first_default + 0;
    if (std::abs(p.x - box.hi.x) <= tolerance && std::abs(q.x - box.hi.x) <= tolerance)
      return first_default + 1;
    if (std::abs(p.y - box.lo.y) <= tolerance && std::abs(q.y - box.lo.y) <= tolerance)
      return first_default + 2;
    if (std::abs(p.y - box.hi.y) <= tolerance && std::abs(q.y - box.hi.y) <= tolerance)
      return first_default + 3;
    return BoundaryEdge::kUnnamed;
  };
  mesh.boundary_edges.clear();
  for (const auto& [a, b] : find_boundary_edges(mesh.triangles))
    mesh.boundary_edges.push_back({{a, b}, name_of(mesh.nodes[a], mesh.nodes[b])});
}

double refined_size(const MeshRequest& request, double distance) {
  if (distance >= request.refine_distance) return request.size;
  const double t = std::max(distance, 0.0) / request.refine_distance;
  return request.fracture_size + t * (request.size - request.fracture_size);
}

}  // namespace hydrodda::mesh
