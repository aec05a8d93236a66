#pragma once
// Results per fracture: for each trace of the scenario (a listed fracture, a joint of a set, a
// row of the fractures file), how far its faces have opened and slid, and how much fluid flows
// along it. What fractures.csv, fractures.pvd and figures/apertures.* show (docs/output.md).
//
// The opening of a face is measured between the two blocks' edges that lie on it, along their
// mean normal. A block moves affinely (DDA's first-order displacement field with its rotation
// applied exactly), so each edge stays straight and its material points move linearly along
// it: the separation of two edges is linear along the face, and its mean (trapezoid rule),
// largest value (at a node) and open length (where the line crosses the threshold) are exact
// between nodes, up to the frame: edges turned θ apart leave the opening ambiguous by a
// factor cos(θ/2) and the shear by the gap × sin(θ/2).

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "coupling/joint_aperture_laws.hpp"
#include "geometry/block_network.hpp"
#include "geometry/face_gauge.hpp"
#include "dda/system.hpp"
#include "hydro/flow_solution.hpp"
#include "hydro/permeability_law.hpp"
#include "mesh/point_locator.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::fractures {

// What a model's blocks were cut from: every trace (its index the fracture id) and the
// network, whose block order is the DDA system's.
struct FractureLayout {
  std::vector<geometry::FractureTrace> traces;
  geometry::BlockNetwork network;
};

// A fracture is open when the opening exceeds the open threshold over at least this share of
// its length: open from end to end but for a stretch at a junction or a tip. A wedge open over
// part of it while the rest carries the load is a closed fracture with an open tip (its
// open_share, open_length and pieces say how much and where), not an open one: the joints of a
// flexed layer open over about half their depth, from its side in tension (the paper's
// flexures: 0.49 to 0.50, where a threshold of a half would flip on round-off).
inline constexpr double kOpenShare = 0.9;

// "listed", "set", "file": a trace's origin as fractures.csv writes it.
std::string origin_name(geometry::TraceSource source);

struct FractureResult {
  int id = 0;
  geometry::TraceOrigin origin;
  double length = 0.0;          // m, of its faces between blocks
  double open_length = 0.0;     // m, where the opening exceeds the threshold
  double open_share = 0.0;      // open_length / length, 0..1
  bool open = false;            // open over at least kOpenShare of its length
  double mean_aperture = 0.0;   // m, mechanical: the opening where open, 0 where closed; mean over the length
  double max_aperture = 0.0;    // m, the largest opening where open
  double max_shear = 0.0;       // m, largest |relative displacement along the face|
  double hydraulic_aperture = 0.0;  // m, mean over the length (its joint type's hydro::JointApertureLaw)
  // Pa, its mean effective normal traction: the compressive contact forces on all its faces
  // over its whole length (force / length; 0 where nothing presses on it).
  double normal_stress = 0.0;
  // Its sharpest wedge tip: the largest rate dw/ds at which its opening grows from a point
  // where it crosses the open threshold (0 when it has none), and that point.
  double tip_opening_angle = 0.0;
  geometry::Point tip;
  std::optional<double> flow;   // m²/s per metre of thickness, along the trace (from → to)
};

// A piece of a fracture between nodes, on the deformed faces (the midline between the two
// blocks), cut where it opens or closes.
struct FracturePiece {
  std::array<geometry::Point, 2> segment;
  int fracture = 0;
  double aperture = 0.0;  // m, mean over the piece
  double shear = 0.0;     // m, mean over the piece
  bool open = false;
  double hydraulic_aperture = 0.0;  // m
};

struct FractureState {
  std::vector<FractureResult> fractures;  // one per trace with a face, by id
  std::vector<FracturePiece> pieces;
};

class FractureMeter {
 public:
  // `node_spacing`: the largest distance between measuring nodes along a face (m); a face gets
  // at least one piece.
  FractureMeter(FractureLayout layout, double node_spacing);

  // The fractures with the blocks at `blocks` (current vertices, in the network's block
  // order, each with its initial vertex count). A point of a face is open where its opening
  // exceeds `open_threshold` (m). The hydraulic apertures follow each fracture's law (`laws`,
  // by fracture id; one law for all converts) with the effective normal stress of the DDA's
  // `contacts` (none: unloaded). Throws std::invalid_argument when the blocks do not fit.
  FractureState measure(std::span<const geometry::Polygon> blocks, double open_threshold,
                        std::span<const dda::ContactInfo> contacts = {},
                        const coupling::JointApertureLaws& laws = {}) const;

  // The flow along each fracture, from the fluid field on `mesh`:
  //   Q_f = (1/L_f) Σ_{e ∈ Z_f} (q_e · t_f) A_e,
  // q_e the element's Darcy flux, A_e its area, t_f the trace's unit direction (from → to),
  // L_f the length of its faces, Z_f the elements whose centroid is nearer to a face of f
  // than to any other face and projects onto that face (not beyond its ends). Q_f is the
  // flux through a section across the fracture, averaged along it: in a tight matrix the flow
  // through the aperture. For one fracture from an inflow to an outflow boundary it is the
  // boundary's flow exactly (the P1 residual identity with the test function s/L).
  // Z_f depends only on the fixed mesh and the traces, so it is found once per run
  // (flow_zones) and each pass only sums the fluxes (add_flow).
  struct FlowZones {
    std::vector<int> fracture;  // per element: the f with e ∈ Z_f, or -1
  };
  FlowZones flow_zones(const mesh::TriangleMesh& mesh) const;
  // `mesh`: the one the zones were found on.
  void add_flow(FractureState& state, const FlowZones& zones, const mesh::TriangleMesh& mesh,
                const hydro::FlowSolution& flow) const;

  const FractureLayout& layout() const { return layout_; }

 private:
  // A node along a face, with the gauge across it there.
  struct Node {
    double s = 0.0;  // m, along the face
    geometry::FaceGauge gauge;
  };
  struct Face {
    geometry::Segment2 segment;
    int fracture = 0;
    std::vector<Node> nodes;
  };
  FractureLayout layout_;
  std::vector<Face> faces_;
};

// Under the cubic law, the sharpest wedge tip: of the fractures whose opening grows from a tip
// (FractureResult::tip_opening_angle), the one with the shortest tip length s*
// (hydro::cubic_law_tip_length with k_m). A joint whose hydraulic aperture at zero opening
// (its fracture's law in `laws`) is already the wedge's opening at s* has no sharp tip and is
// left out. None without a sharp tip.
struct WedgeTip {
  int fracture = 0;
  geometry::Point point;
  double opening_angle = 0.0;  // rad
  double length = 0.0;         // s*, m
};
std::optional<WedgeTip> find_sharpest_wedge_tip(const FractureState& state, double matrix_permeability,
                                                const coupling::JointApertureLaws& laws);

// The fluid element a sharp wedge tip lies in: the longest edge of the triangle that holds the
// tip's point, and how far the point lies from its fracture's trace as given. A generated mesh
// is refined along the traces; the blocks carry a tip away from them as they move (the
// asymmetric flexures' by 2 mm), into elements that grow from there towards mesh.size.
struct WedgeTipElement {
  WedgeTip tip;
  double element_size = 0.0;    // m
  double trace_distance = 0.0;  // m
};
// The fluid element of `tip` (none when its point lies outside the mesh). `locator` is the
// mesh's; `traces` the meter's layout's, by fracture id.
std::optional<WedgeTipElement> find_wedge_tip_element(const WedgeTip& tip, const mesh::TriangleMesh& mesh,
                                                      const mesh::PointLocator& locator,
                                                      std::span<const geometry::FractureTrace> traces);
// The elements of the sharp tips (those find_sharpest_wedge_tip weighs) inside the mesh, the
// least resolved first: by element size over s*, largest first.
std::vector<WedgeTipElement> find_wedge_tip_elements(const FractureState& state, double matrix_permeability,
                                                     const coupling::JointApertureLaws& laws,
                                                     const mesh::TriangleMesh& mesh,
                                                     const mesh::PointLocator& locator,
                                                     std::span<const geometry::FractureTrace> traces);

// Whether the element at a tip resolves it: at most s*/2 across.
inline bool resolves_wedge_tip(const WedgeTipElement& e) { return e.element_size <= 0.5 * e.tip.length; }


}  // namespace hydrodda::fractures
