#include "dda/initial_stress.hpp"

#include <algorithm>
#include <vector>

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

namespace {

// The parameters s in (0, 1) along p→q where the face crosses a knot of a layered field, in
// increasing order, with 0 and 1 at the ends.
std::vector<double> find_knot_crossings(const StressField& field, Point p, Point q) {
  std::vector<double> at{0.0};
  for (const StressKnot& k : field.knots) {
    const double s = (k.y - p.y) / (q.y - p.y);  // ±inf or NaN for a level face: not kept
    if (s > 0.0 && s < 1.0) at.push_back(s);
  }
  std::sort(at.begin() + 1, at.end());
  at.push_back(1.0);
  return at;
}

}  // namespace

Point compute_face_load(const StressField& field, Point p, Point q, Point n) {
  const Point tp = traction_of(field.at(p.y), n);
  const Point tq = traction_of(field.at(q.y), n);
  const std::vector<double> pieces = find_knot_crossings(field, p, q);
  if (pieces.size() == 2) return geometry::distance(p, q) / 6.0 * (2.0 * tp + tq);
  // A layered field is linear on each piece between knots, and p's weight 1 − s linear along
  // the whole face: their product is quadratic on each piece, which Simpson's rule integrates
  // exactly, ∫ t (1 − s) ds = Δs/6 (f(s0) + 4 f(sm) + f(s1)) × L.
  const auto weighted = [&](double s) { return (1.0 - s) * traction_of(field.at(p.y + s * (q.y - p.y)), n); };
  Point force{};
  for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
    const double s0 = pieces[i], s1 = pieces[i + 1];
    force += (s1 - s0) / 6.0 * (weighted(s0) + 4.0 * weighted(0.5 * (s0 + s1)) + weighted(s1));
  }
  return geometry::distance(p, q) * force;
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
