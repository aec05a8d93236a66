#include "dda/initial_stress.hpp"

#include "dda/contact_detection.hpp"

namespace hydrodda::dda {

namespace {

Point traction_of(const std::array<double, 3>& s, Point n) { return {s[0] * n.x + s[2] * n.y, s[2] * n.x + s[1] * n.y}; }

// The faces of block i a contact carries: vertex `vertex` against edge `edge` of block j, the
// faces incident to the vertex that lie along the edge, as parameters along it from a with unit
// direction s.
struct ContactFaces {
  Point a, s;
  FacesAlongEdge faces;
};
ContactFaces find_contact_faces(std::span<const Point> polygon_i, int vertex, std::span<const Point> polygon_j,
                                int edge, double distance) {
  const int ni = static_cast<int>(polygon_i.size());
  const int nj = static_cast<int>(polygon_j.size());
  const Point a = polygon_j[edge];
  const Point b = polygon_j[(edge + 1) % nj];
  const Point s = (b - a) / geometry::distance(a, b);
  return {a, s,
          find_faces_along_edge(polygon_i[vertex], polygon_i[(vertex + ni - 1) % ni], polygon_i[(vertex + 1) % ni], a,
                                b, distance)};
}

}  // namespace

Point compute_face_load(const StressField& field, Point p, Point q, Point n) {
  const Point tp = traction_of(field.at(p.y), n);
  const Point tq = traction_of(field.at(q.y), n);
  return geometry::distance(p, q) / 6.0 * (2.0 * tp + tq);
}

ContactPreload compute_contact_preload(const StressField& field, std::span<const Point> polygon_i, int vertex,
                                       std::span<const Point> polygon_j, int edge, double distance) {
  const auto [a, s, faces] = find_contact_faces(polygon_i, vertex, polygon_j, edge, distance);
  const Point outward_j{s.y, -s.x};  // out of block j (counter-clockwise), into block i
  Point force{};  // on block i, whose outward normal on these faces is −outward_j
  for (int k = 0; k < faces.count; ++k)
    force += compute_face_load(field, a + faces.face[k].near * s, a + faces.face[k].far * s, -1.0 * outward_j);
  return {dot(force, outward_j), dot(force, s)};
}

double compute_contact_fluid_push(const FaceShare& share, int block_i, std::span<const Point> polygon_i, int vertex,
                                  std::span<const Point> polygon_j, int edge, double distance) {
  const auto [a, s, faces] = find_contact_faces(polygon_i, vertex, polygon_j, edge, distance);
  double push = 0.0;
  for (int k = 0; k < faces.count; ++k) push += share(block_i, a + faces.face[k].near * s, a + faces.face[k].far * s);
  return push;
}

}  // namespace hydrodda::dda
