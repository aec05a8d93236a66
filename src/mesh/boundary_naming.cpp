#include <algorithm>
#include <array>
#include <cmath>

#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {

void name_boundary_edges(TriangleMesh& mesh, const std::vector<NamedSegment>& segments,
                         const geometry::Box& box) {
  const double tolerance = 1e-9 * std::max(box.width(), box.height());
  // Names in order: each user name once, then the defaults the user did not redefine.
  mesh.boundary_names.clear();
  std::vector<int> index_of_segment;
  for (const NamedSegment& s : segments) {
    int index = find_boundary(mesh, s.name);
    if (index < 0) {
      index = static_cast<int>(mesh.boundary_names.size());
      mesh.boundary_names.push_back(s.name);
    }
    index_of_segment.push_back(index);
  }
  std::array<int, 4> index_of_side{};
  for (int side = 0; side < 4; ++side) {
    const std::string& name = kDefaultBoundaryNames[side];
    const bool redefined = find_boundary(mesh, name) >= 0;
    index_of_side[side] = redefined ? BoundaryEdge::kUnnamed : static_cast<int>(mesh.boundary_names.size());
    if (!redefined) mesh.boundary_names.push_back(name);
  }

  auto on_segment = [&](Point p, Point a, Point b) {
    return geometry::distance_to_segment(p, a, b) <= tolerance;
  };
  auto name_of = [&](Point p, Point q) {
    for (std::size_t s = 0; s < segments.size(); ++s)
      if (on_segment(p, segments[s].from, segments[s].to) &&
          on_segment(q, segments[s].from, segments[s].to))
        return index_of_segment[s];
    if (std::abs(p.x - box.lo.x) <= tolerance && std::abs(q.x - box.lo.x) <= tolerance)
      return index_of_side[0];
    if (std::abs(p.x - box.hi.x) <= tolerance && std::abs(q.x - box.hi.x) <= tolerance)
      return index_of_side[1];
    if (std::abs(p.y - box.lo.y) <= tolerance && std::abs(q.y - box.lo.y) <= tolerance)
      return index_of_side[2];
    if (std::abs(p.y - box.hi.y) <= tolerance && std::abs(q.y - box.hi.y) <= tolerance)
      return index_of_side[3];
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

double refined_size(const MeshRequest& request, double line_distance, Point p) {
  double size = refined_size(request, line_distance);  // `size` where no line is within reach
  for (const RefinePoint& r : request.refinement_points) {
    const double d = geometry::distance(p, r.point);
    if (d < r.radius) size = std::min(size, r.size + d / r.radius * (request.size - r.size));
  }
  return size;
}

}  // namespace hydrodda::mesh
