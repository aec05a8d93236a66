#include "dda/selection.hpp"

#include "dda/initial_stress.hpp"

namespace hydrodda::dda {

std::vector<VertexRef> select_vertices_on_segment(std::span<const BlockDefinition> blocks,
                                                  Point a, Point b, double tolerance) {
  std::vector<VertexRef> out;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Polygon& p = blocks[i].polygon;
    for (std::size_t v = 0; v < p.size(); ++v)
      if (geometry::distance_to_segment(p[v], a, b) <= tolerance)
        out.push_back({static_cast<int>(i), static_cast<int>(v)});
  }
  return out;
}

std::vector<EdgeRef> select_edges_on_segment(std::span<const BlockDefinition> blocks, Point a,
                                             Point b, double tolerance) {
  std::vector<EdgeRef> out;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Polygon& p = blocks[i].polygon;
    const std::size_t n = p.size();
    for (std::size_t e = 0; e < n; ++e)
      if (geometry::distance_to_segment(p[e], a, b) <= tolerance &&
          geometry::distance_to_segment(p[(e + 1) % n], a, b) <= tolerance)
        out.push_back({static_cast<int>(i), static_cast<int>(e)});
  }
  return out;
}

std::vector<EdgeTraction> make_tractions_on_segment(std::span<const BlockDefinition> blocks,
                                                    Point a, Point b, double tolerance,
                                                    const numerics::TimeTable& normal_a, const numerics::TimeTable& normal_b,
                                                    const numerics::TimeTable& shear_a, const numerics::TimeTable& shear_b) {
  const Point ab = b - a;
  const double length2 = dot(ab, ab);
  // Linear interpolation by the projection of an edge end on ab.
  const auto at = [&](Point p, const numerics::TimeTable& va, const numerics::TimeTable& vb) {
    const double t = length2 > 0 ? dot(p - a, ab) / length2 : 0.0;
    return numerics::TimeTable::between(va, vb, t);
  };
  std::vector<EdgeTraction> out;
  for (EdgeRef e : select_edges_on_segment(blocks, a, b, tolerance)) {
    const Polygon& p = blocks[e.block].polygon;
    const Point p0 = p[e.edge];
    const Point p1 = p[(e.edge + 1) % p.size()];
    out.push_back({e.block, e.edge, at(p0, normal_a, normal_b), at(p1, normal_a, normal_b),
                   at(p0, shear_a, shear_b), at(p1, shear_a, shear_b)});
  }
  return out;
}

std::vector<Roller> make_rollers_on_segment(std::span<const BlockDefinition> blocks, Point a, Point b,
                                            double tolerance, const std::optional<StressField>& initial_stress) {
  const Point along = (b - a) / geometry::distance(a, b);
  std::vector<Roller> out;
  for (VertexRef v : select_vertices_on_segment(blocks, a, b, tolerance)) {
    const Polygon& p = blocks[v.block].polygon;
    const std::size_t n = p.size();
    // The segment's normal that points away from the block.
    Point normal{along.y, -along.x};
    if (dot(geometry::centroid(p) - a, normal) > 0.0) normal = -1.0 * normal;
    Roller roller{v.block, v.vertex, normal, 0.0};
    const Point here = p[v.vertex];
    const std::array<Point, 2> neighbours{p[(v.vertex + n - 1) % n], p[(v.vertex + 1) % n]};
    for (int k = 0; k < 2; ++k) {
      roller.faces_along[k] = geometry::distance_to_segment(neighbours[k], a, b) <= tolerance;
      // The field's push on the vertex's share of its faces along the boundary.
      if (initial_stress && roller.faces_along[k])
        roller.preload -= dot(compute_face_load(*initial_stress, here, neighbours[k], normal), normal);
    }
    out.push_back(roller);
  }
  return out;
}

}  // namespace hydrodda::dda
