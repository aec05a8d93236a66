#include "fractures/fracture_results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "coupling/embedded_joints.hpp"
#include "numerics/parallel.hpp"
#include "geometry/spatial_grid.hpp"

namespace hydrodda::fractures {

using geometry::Point;

namespace {

Point unit_normal_left(Point d) { return Point{-d.y, d.x}; }

}  // namespace

std::string origin_name(geometry::TraceSource source) {
  switch (source) {
    case geometry::TraceSource::listed: return "listed";
    case geometry::TraceSource::joint_set: return "set";
    case geometry::TraceSource::file: return "file";
  }
  return "listed";
}

FractureMeter::FractureMeter(FractureLayout layout, double node_spacing) : layout_(std::move(layout)) {
  const geometry::FaceGaugeFinder finder(layout_.network);
  for (const geometry::FractureFace& face : layout_.network.faces) {
    const Point d0 = face.segment.to - face.segment.from;
    const double length = geometry::norm(d0);
    if (!(length > 0.0)) continue;
    const Point d = d0 / length;
    Face measured{face.segment, face.fracture, {}};
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / node_spacing)));
    for (int k = 0; k <= pieces; ++k) {
      const double s = length * k / pieces;
      if (const auto gauge = finder.find(face, face.segment.from + d * s)) measured.nodes.push_back({s, *gauge});
    }
    if (measured.nodes.size() >= 2) faces_.push_back(std::move(measured));
  }
}

FractureState FractureMeter::measure(std::span<const geometry::Polygon> blocks, double open_threshold,
                                     std::span<const dda::ContactInfo> contacts,
                                     const coupling::JointApertureLaws& laws) const {
  const geometry::BlockNetwork& network = layout_.network;
  if (blocks.size() != network.blocks.size())
    throw std::invalid_argument(fmt::format("fracture results: {} blocks given, the network has {}", blocks.size(),
                                            network.blocks.size()));
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (blocks[b].size() != network.blocks[b].size())
      throw std::invalid_argument(fmt::format("fracture results: block {} has {} vertices, it was cut with {}", b,
                                              blocks[b].size(), network.blocks[b].size()));

  FractureState state;
  std::vector<int> index(layout_.traces.size(), -1);
  std::vector<coupling::FaceKey> piece_face;  // per piece: the face it lies on
  std::vector<double> piece_length;           // per piece: m along the face
  std::map<coupling::FaceKey, double> closed_length;
  for (const Face& face : faces_) {
    const coupling::FaceKey key{face.fracture, std::min(face.nodes[0].gauge.minus.block, face.nodes[0].gauge.plus.block),
                                std::max(face.nodes[0].gauge.minus.block, face.nodes[0].gauge.plus.block)};
    if (index[face.fracture] < 0) {
      index[face.fracture] = static_cast<int>(state.fractures.size());
      FractureResult r;
      r.id = face.fracture;
      r.origin = layout_.traces[face.fracture].origin;
      state.fractures.push_back(r);
    }
    FractureResult& result = state.fractures[index[face.fracture]];
    struct Measured {
      double s, opening, shear;
      Point midpoint;
    };
    std::vector<Measured> m;
    for (const Node& node : face.nodes) {
      const geometry::GaugeReading g = geometry::read_gauge(node.gauge, blocks, network.blocks);
      m.push_back({node.s, g.opening, g.shear, g.midpoint});
    }
    const auto add_piece = [&](const Measured& a, const Measured& b) {
      const double ds = b.s - a.s;
      if (!(ds > 0.0)) return;
      // Pieces are cut where the opening crosses the threshold, so both ends lie on one side.
      // Openings under it are the contacts' own tolerance, not a gap: no aperture.
      const bool open = 0.5 * (a.opening + b.opening) > open_threshold;
      const double aperture = open ? 0.5 * (a.opening + b.opening) : 0.0;
      result.length += ds;
      if (open) result.open_length += ds;
      result.mean_aperture += aperture * ds;  // divided by the length below
      if (!open) closed_length[key] += ds;
      state.pieces.push_back({{a.midpoint, b.midpoint}, face.fracture, aperture, 0.5 * (a.shear + b.shear), open});
      piece_face.push_back(key);
      piece_length.push_back(ds);
    };
    for (std::size_t k = 0; k < m.size(); ++k) {
      if (m[k].opening > open_threshold) result.max_aperture = std::max(result.max_aperture, m[k].opening);
      result.max_shear = std::max(result.max_shear, std::abs(m[k].shear));
      if (k == 0) continue;
      const Measured& a = m[k - 1];
      const Measured& b = m[k];
      if ((a.opening - open_threshold) * (b.opening - open_threshold) < 0.0) {
        // Cut where the opening crosses the threshold: the piece opens or closes there.
        const double w = (open_threshold - a.opening) / (b.opening - a.opening);
        const Measured cut{a.s + w * (b.s - a.s), open_threshold, a.shear + w * (b.shear - a.shear),
                           a.midpoint + (b.midpoint - a.midpoint) * w};
        // A wedge tip: the opening is linear between nodes, so this is its slope there.
        const double angle = std::abs(b.opening - a.opening) / (b.s - a.s);
        if (angle > result.tip_opening_angle) {
          result.tip_opening_angle = angle;
          result.tip = cut.midpoint;
        }
        add_piece(a, cut);
        add_piece(cut, b);
      } else {
        add_piece(a, b);
      }
    }
  }
  // The hydraulic aperture of each piece by its fracture's law (its joint type's
  // hydro::JointApertureLaw::on_face), as the flow takes it.
  const std::map<coupling::FaceKey, double> forces = coupling::contact_forces_by_face(contacts, network.edge_fractures);
  std::vector<double> fracture_force(layout_.traces.size(), 0.0);
  for (const auto& [key, force] : forces)
    if (key.fracture < static_cast<int>(fracture_force.size())) fracture_force[key.fracture] += force;
  std::map<coupling::FaceKey, double> face_length;
  for (std::size_t p = 0; p < state.pieces.size(); ++p) face_length[piece_face[p]] += piece_length[p];
  for (std::size_t p = 0; p < state.pieces.size(); ++p) {
    FracturePiece& piece = state.pieces[p];
    const auto force = forces.find(piece_face[p]);
    piece.hydraulic_aperture = laws.of_fracture(piece.fracture)
                                   .on_face(force == forces.end() ? 0.0 : force->second, face_length.at(piece_face[p]),
                                            closed_length[piece_face[p]], piece.aperture, open_threshold);
    FractureResult& r = state.fractures[index[piece.fracture]];
    r.hydraulic_aperture += piece.hydraulic_aperture * piece_length[p];
  }
  // The fracture's normal stress is its mean over its whole length: the force on its closed
  // part over that part alone is the stress where it touches (what the closure above needs),
  // which a short closed remainder beside an open wedge blows up (to GPa under a 10 MPa load).
  for (FractureResult& r : state.fractures) {
    if (r.length > 0.0) {
      r.normal_stress = fracture_force[r.id] / r.length;
      r.mean_aperture /= r.length;
      r.hydraulic_aperture /= r.length;
      r.open_share = std::clamp(r.open_length / r.length, 0.0, 1.0);
    }
    r.open = r.open_share >= kOpenShare;
  }
  std::sort(state.fractures.begin(), state.fractures.end(),
            [](const FractureResult& a, const FractureResult& b) { return a.id < b.id; });
  return state;
}

// For each element, the face nearest its centroid among those it projects onto, the lower
// face index on a tie, through a spatial grid of the faces (SpatialGrid::nearest; a face's
// distance is at least its box's): the loop over every face took 25 s for the 10,200-block
// seal's 1.08 million elements and 40,000 faces.
FractureMeter::FlowZones FractureMeter::flow_zones(const mesh::TriangleMesh& mesh) const {
  FlowZones zones;
  zones.fracture.assign(static_cast<std::size_t>(mesh.triangle_count()), -1);
  std::vector<geometry::Box> boxes;
  double total_length = 0.0;
  for (const Face& face : faces_) {
    geometry::Box box;
    box.add(face.segment.from);
    box.add(face.segment.to);
    boxes.push_back(box);
    total_length += geometry::norm(face.segment.to - face.segment.from);
  }
  const geometry::SpatialGrid grid(boxes);
  const double first_reach = faces_.empty() ? 0.0 : total_length / faces_.size();
  // Each element on its own (the grid's queries keep no state), over the threads.
  numerics::for_each_index(mesh.triangle_count() >= 20000, mesh.triangles.size(), [&](std::size_t element) {
    const int t = static_cast<int>(element);
    const Point c = mesh::triangle_centroid(mesh, t);
    // The distance to the face's line where c projects onto the face, else none.
    const int nearest = grid.nearest(c, first_reach, [&](int k) {
      const geometry::Segment2& seg = faces_[k].segment;
      const Point d = seg.to - seg.from;
      const double length2 = geometry::dot(d, d);
      const double along = geometry::dot(c - seg.from, d);
      if (along < 0.0 || along > length2) return std::numeric_limits<double>::infinity();
      return std::abs(geometry::dot(c - seg.from, unit_normal_left(d))) / std::sqrt(length2);
    });
    if (nearest >= 0) zones.fracture[t] = faces_[nearest].fracture;
  });
  return zones;
}

void FractureMeter::add_flow(FractureState& state, const FlowZones& zones, const mesh::TriangleMesh& mesh,
                             const hydro::FlowSolution& flow) const {
  if (flow.flux.size() != zones.fracture.size())
    throw std::invalid_argument("fracture results: the flow solution does not fit the mesh");
  std::vector<double> integral(layout_.traces.size(), 0.0);  // Σ (q_e · t_f) A_e
  std::vector<Point> direction(layout_.traces.size());
  for (std::size_t f = 0; f < layout_.traces.size(); ++f) {
    const Point d = layout_.traces[f].segment.to - layout_.traces[f].segment.from;
    direction[f] = d / geometry::norm(d);
  }
  // A_e from the mesh each time: a few milliseconds a pass at a million triangles, where a
  // kept copy would hold 8 MB for the whole run.
  for (std::size_t t = 0; t < zones.fracture.size(); ++t) {
    const int f = zones.fracture[t];
    if (f >= 0) integral[f] += geometry::dot(flow.flux[t], direction[f]) * mesh::triangle_area(mesh, static_cast<int>(t));
  }
  for (FractureResult& r : state.fractures)
    r.flow = r.length > 0.0 ? integral[r.id] / r.length : 0.0;
}

namespace {

// The sharp wedge tips: those whose joint's hydraulic aperture at zero opening (its fracture's
// law) is less than the wedge's opening at s*.
std::vector<WedgeTip> find_sharp_wedge_tips(const FractureState& state, double matrix_permeability,
                                            const coupling::JointApertureLaws& laws) {
  std::vector<WedgeTip> tips;
  for (const FractureResult& r : state.fractures) {
    if (!(r.tip_opening_angle > 0.0)) continue;
    const double length = hydro::cubic_law_tip_length(r.tip_opening_angle, matrix_permeability);
    if (laws.of_fracture(r.id).at_zero_stress() >= r.tip_opening_angle * length) continue;
    tips.push_back(WedgeTip{r.id, r.tip, r.tip_opening_angle, length});
  }
  return tips;
}

}  // namespace

std::optional<WedgeTip> find_sharpest_wedge_tip(const FractureState& state, double matrix_permeability,
                                                const coupling::JointApertureLaws& laws) {
  std::optional<WedgeTip> sharpest;
  for (const WedgeTip& tip : find_sharp_wedge_tips(state, matrix_permeability, laws))
    if (!sharpest || tip.length < sharpest->length) sharpest = tip;
  return sharpest;
}

std::optional<WedgeTipElement> find_wedge_tip_element(const WedgeTip& tip, const mesh::TriangleMesh& mesh,
                                                      const mesh::PointLocator& locator,
                                                      std::span<const geometry::FractureTrace> traces) {
  const int triangle = locator.locate(tip.point);
  if (triangle < 0) return std::nullopt;
  WedgeTipElement element{tip};
  const auto& corners = mesh.triangles[static_cast<std::size_t>(triangle)];
  for (int i = 0; i < 3; ++i)
    element.element_size = std::max(element.element_size, geometry::distance(mesh.nodes[corners[i]],
                                                                              mesh.nodes[corners[(i + 1) % 3]]));
  const geometry::FractureTrace& trace = traces[static_cast<std::size_t>(tip.fracture)];
  element.trace_distance = geometry::distance_to_segment(tip.point, trace.segment.from, trace.segment.to);
  return element;
}

std::vector<WedgeTipElement> find_wedge_tip_elements(const FractureState& state, double matrix_permeability,
                                                     const coupling::JointApertureLaws& laws,
                                                     const mesh::TriangleMesh& mesh,
                                                     const mesh::PointLocator& locator,
                                                     std::span<const geometry::FractureTrace> traces) {
  std::vector<WedgeTipElement> elements;
  for (const WedgeTip& tip : find_sharp_wedge_tips(state, matrix_permeability, laws))
    if (const std::optional<WedgeTipElement> element = find_wedge_tip_element(tip, mesh, locator, traces))
      elements.push_back(*element);
  std::stable_sort(elements.begin(), elements.end(), [](const WedgeTipElement& a, const WedgeTipElement& b) {
    return a.element_size / a.tip.length > b.element_size / b.tip.length;
  });
  return elements;
}

}  // namespace hydrodda::fractures
