#include "coupling/embedded_joints.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "geometry/spatial_grid.hpp"

namespace hydrodda::coupling {

using geometry::Point;

namespace {

struct SegmentPiece {
  double t0 = 0.0, t1 = 0.0;  // along the segment, a + t (b − a)
  bool on_edge = false;       // it runs along one of the triangle's edges
};

// The part of segment ab inside triangle `tri` (Cyrus–Beck: intersect the three half-planes
// of the edges along the segment). A segment on an edge's line (within 1e-9 of the sizes) is
// inside, and flagged, so that a face along an edge shared by two elements is counted half in
// each.
std::optional<SegmentPiece> clip_to_triangle(Point a, Point b, const std::array<Point, 3>& tri) {
  const double sign = geometry::orient(tri[0], tri[1], tri[2]) > 0.0 ? 1.0 : -1.0;
  const Point d = b - a;
  const double length = geometry::norm(d);
  SegmentPiece piece{0.0, 1.0, false};
  for (int k = 0; k < 3; ++k) {
    const Point p = tri[k], e = tri[(k + 1) % 3] - p;
    const double edge_length = geometry::norm(e);
    // Inside where sign · e × (x − p) ≥ 0: f(t) = f0 + t df.
    const double f0 = sign * geometry::cross(e, a - p);
    const double df = sign * geometry::cross(e, d);
    const double tolerance = 1e-9 * edge_length * std::max(length, edge_length);
    if (std::abs(df) <= 1e-12 * edge_length * length) {  // parallel to the edge
      if (f0 < -tolerance) return std::nullopt;
      if (f0 <= tolerance) piece.on_edge = true;
      continue;
    }
    const double t = -f0 / df;
    if (df > 0.0)
      piece.t0 = std::max(piece.t0, t);
    else
      piece.t1 = std::min(piece.t1, t);
  }
  if (!(piece.t1 - piece.t0 > 1e-12)) return std::nullopt;
  return piece;
}

FaceKey face_key(int fracture, int block_a, int block_b) {
  return {fracture, std::min(block_a, block_b), std::max(block_a, block_b)};
}

}  // namespace

std::map<FaceKey, double> contact_forces_by_face(std::span<const dda::ContactInfo> contacts,
                                                 const std::vector<std::vector<int>>& edge_fractures) {
  std::map<FaceKey, double> forces;
  for (const dda::ContactInfo& c : contacts) {
    if (c.state == dda::ContactState::open || !(c.normal_force > 0.0)) continue;
    const std::vector<int>& edges = edge_fractures.at(static_cast<std::size_t>(c.key.block_j));
    const int fracture = c.key.edge < static_cast<int>(edges.size()) ? edges[c.key.edge] : -1;
    if (fracture < 0) continue;
    forces[face_key(fracture, c.key.block_i, c.key.block_j)] += c.normal_force;
  }
  return forces;
}

EmbeddedJoints::EmbeddedJoints(const mesh::TriangleMesh& mesh, geometry::BlockNetwork network,
                               JointApertureLaws laws, int first_bond_fracture)
    : network_(std::move(network)), laws_(std::move(laws)), first_bond_(first_bond_fracture) {
  if (first_bond_ >= 0)
    for (const geometry::FractureFace& face : network_.faces)
      bond_count_ = std::max(bond_count_, face.fracture - first_bond_ + 1);
  const int elements = mesh.triangle_count();
  std::vector<geometry::Box> boxes;
  for (int t = 0; t < elements; ++t) {
    element_area_.push_back(mesh::triangle_area(mesh, t));
    const auto& tri = mesh.triangles[t];
    boxes.push_back(geometry::bounding_box(
        std::array<Point, 3>{mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]}));
  }
  const geometry::SpatialGrid grid(boxes);
  const geometry::FaceGaugeFinder finder(network_);
  for (const geometry::FractureFace& face : network_.faces) {
    const Point a = face.segment.from, b = face.segment.to;
    const double length = geometry::distance(a, b);
    if (!(length > 0.0)) continue;
    const Point direction = (b - a) / length;
    grid.for_each_overlap(geometry::bounding_box(std::array<Point, 2>{a, b}), [&](int t) {
      const auto& tri = mesh.triangles[t];
      const auto piece = clip_to_triangle(a, b, {mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]});
      if (!piece) return;
      const auto gauge = finder.find(face, a + (b - a) * (0.5 * (piece->t0 + piece->t1)));
      if (!gauge) return;
      const double inside = (piece->t1 - piece->t0) * length * (piece->on_edge ? 0.5 : 1.0);
      crossings_.push_back({t, face_key(face.fracture, gauge->minus.block, gauge->plus.block), inside, direction,
                            *gauge});
    });
  }
  for (const JointCrossing& c : crossings_)
    zero_stress_aperture_.push_back(laws_.of_fracture(c.face.fracture).at_zero_stress());
  // Each face's length over its crossings inside the mesh, found once: the mesh is fixed.
  std::map<FaceKey, double> length_of_face;
  for (const JointCrossing& c : crossings_) length_of_face[c.face] += c.length;
  for (const JointCrossing& c : crossings_) face_length_.push_back(length_of_face.at(c.face));
  // The zone: the crossed elements and every element sharing a node with one.
  std::vector<char> near_node(mesh.nodes.size(), 0);
  for (const JointCrossing& c : crossings_)
    for (int v : mesh.triangles[c.element]) near_node[v] = 1;
  zone_.assign(static_cast<std::size_t>(elements), 0);
  for (int t = 0; t < elements; ++t)
    for (int v : mesh.triangles[t]) zone_[t] = zone_[t] || near_node[v];
}

std::vector<double> EmbeddedJoints::apertures(std::span<const geometry::Polygon> blocks,
                                              std::span<const dda::ContactInfo> contacts,
                                              double open_threshold, std::span<const char> broken_bonds) const {
  if (bond_count_ > 0 && broken_bonds.size() < static_cast<std::size_t>(bond_count_))
    throw std::invalid_argument("joint apertures: the state of " + std::to_string(bond_count_) + " bonds is needed, " +
                                std::to_string(broken_bonds.size()) + " given");
  const auto intact = [&](const JointCrossing& c) {
    const int bond = bond_of(c);
    return bond >= 0 && broken_bonds[static_cast<std::size_t>(bond)] == 0;
  };
  if (blocks.size() != network_.blocks.size())
    throw std::invalid_argument("joint apertures: " + std::to_string(blocks.size()) + " blocks given, the network has " +
                                std::to_string(network_.blocks.size()));
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (blocks[b].size() != network_.blocks[b].size())
      throw std::invalid_argument("joint apertures: block " + std::to_string(b) + " has " +
                                  std::to_string(blocks[b].size()) + " vertices, it was cut with " +
                                  std::to_string(network_.blocks[b].size()));
  // Each face's closed length over its crossings inside the mesh.
  std::vector<double> opening(crossings_.size());
  std::map<FaceKey, double> closed_length;
  for (std::size_t c = 0; c < crossings_.size(); ++c) {
    if (intact(crossings_[c])) continue;
    opening[c] = geometry::read_gauge(crossings_[c].gauge, blocks, network_.blocks).opening;
    if (!(opening[c] > open_threshold)) closed_length[crossings_[c].face] += crossings_[c].length;
  }
  const std::map<FaceKey, double> forces = contact_forces_by_face(contacts, network_.edge_fractures);
  std::vector<double> aperture(crossings_.size());
  for (std::size_t c = 0; c < crossings_.size(); ++c) {
    const JointCrossing& crossing = crossings_[c];
    if (intact(crossing)) continue;  // rock: no fracture the flow sees
    const hydro::JointApertureLaw& law = laws_.of_fracture(crossing.face.fracture);
    const auto found = forces.find(crossing.face);
    const double force = found == forces.end() ? 0.0 : found->second;
    // A broken bond's face is a sub-block's, as short as the sub-blocks that resolve a crack,
    // and the tip of a crack opens part of one for real: each point of it by its own gap.
    hydro::JointApertureLaw point_law = law;
    if (bond_of(crossing) >= 0) point_law.opening = hydro::HydraulicOpening::local;
    const auto closed = closed_length.find(crossing.face);
    aperture[c] = point_law.on_face(force, face_length_[c], closed == closed_length.end() ? 0.0 : closed->second,
                                    opening[c], open_threshold);
  }
  return aperture;
}

std::vector<hydro::PermeabilityTensor> EmbeddedJoints::permeability(std::span<const double> isotropic,
                                                                    std::span<const double> apertures) const {
  if (isotropic.size() != element_area_.size() || apertures.size() != crossings_.size())
    throw std::invalid_argument("joint permeability: one value per element and one aperture per crossing are needed");
  std::vector<hydro::PermeabilityTensor> k(isotropic.size());
  for (std::size_t e = 0; e < k.size(); ++e) k[e] = {isotropic[e], 0.0, isotropic[e]};
  for (std::size_t c = 0; c < crossings_.size(); ++c) {
    const JointCrossing& crossing = crossings_[c];
    const hydro::PermeabilityTensor j = hydro::embedded_fracture_permeability(
        apertures[c], crossing.length, element_area_[crossing.element], crossing.direction);
    hydro::PermeabilityTensor& total = k[crossing.element];
    total.xx += j.xx;
    total.xy += j.xy;
    total.yy += j.yy;
  }
  return k;
}

double largest_principal_value(const hydro::PermeabilityTensor& k) {
  const double half_difference = 0.5 * (k.xx - k.yy);
  return 0.5 * (k.xx + k.yy) + std::sqrt(half_difference * half_difference + k.xy * k.xy);
}

}  // namespace hydrodda::coupling
