#pragma once
// Joints as embedded fractures in the fixed fluid mesh. Each element a joint's face crosses
// takes the joint's transmissivity a³/12 along the face over the length of it inside the
// element (hydro::embedded_fracture_permeability), so a joint carries a³/12 × ∇h·t whatever
// the elements' size, closed or open. The hydraulic aperture a at each crossing follows the
// law of its fracture's joint type (JointApertureLaws, hydro::JointApertureLaw::on_face): along a
// face that carries a compressive contact force, the Barton–Bandis closure under the face's mean
// effective normal stress σn (that force over the face's length); along one that carries none,
// a(0) + the opening where the gauge across the face there is open, a(0) where it is not.
//
// One transmissivity per joint: the clipped open area of the elements a joint crosses, and of
// their neighbours, no longer enters the porosity law there (those elements take the matrix
// permeability, `zone()`), so an open gap is not counted twice. Open area elsewhere (a gap
// along the domain boundary) keeps the porosity law.
//
// The crossings are found once, on the faces as cut (before the initial aperture opened
// them): the mesh is fixed and the blocks move little against it.

#include <compare>
#include <map>
#include <span>
#include <vector>

#include "dda/system.hpp"
#include "geometry/block_network.hpp"
#include "geometry/face_gauge.hpp"
#include "hydro/fluid.hpp"
#include "hydro/permeability_law.hpp"
#include "coupling/joint_aperture_laws.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::coupling {

// A face between two blocks along one fracture (the blocks in increasing order).
struct FaceKey {
  int fracture = 0;
  int low_block = 0, high_block = 0;
  friend auto operator<=>(const FaceKey&, const FaceKey&) = default;
};

// Σ of the compressive normal forces (N per metre) of the contacts on each face: a contact of
// a vertex of block_i against an edge of block_j lies on the fracture that edge lies on
// (`edge_fractures`, per block, per edge; −1 on the domain boundary, skipped).
std::map<FaceKey, double> contact_forces_by_face(std::span<const dda::ContactInfo> contacts,
                                                 const std::vector<std::vector<int>>& edge_fractures);

// A piece of a joint face inside one element.
struct JointCrossing {
  int element = 0;
  FaceKey face;
  double length = 0.0;        // m inside the element; half of it where the face runs along an element edge
  geometry::Point direction;  // unit, along the face
  geometry::FaceGauge gauge;  // across the face at the piece's middle
};

class EmbeddedJoints {
 public:
  // Keeps a copy of the network; finds each face's pieces in the mesh's elements. Each face
  // takes the law of its fracture (`laws`, by the network's fracture ids).
  // Fracture ids from `first_bond_fracture` on (≥ 0) are bonds between sub-blocks, bond
  // id = fracture − first_bond_fracture: rock while intact (no transmissivity), a joint of
  // their type once broken (apertures' `broken_bonds`). −1: no bonds.
  EmbeddedJoints(const mesh::TriangleMesh& mesh, geometry::BlockNetwork network, JointApertureLaws laws,
                 int first_bond_fracture = -1);
  // Every joint of one law.
  EmbeddedJoints(const mesh::TriangleMesh& mesh, geometry::BlockNetwork network, hydro::JointApertureLaw law)
      : EmbeddedJoints(mesh, std::move(network), JointApertureLaws(law)) {}

  // The hydraulic aperture at each crossing with the blocks at `blocks` (the network's block
  // and vertex order) and the DDA's contacts, by the law of the crossing's fracture: a gauge
  // is open where its opening exceeds `open_threshold` (m). A crossing of a bond conducts only
  // where `broken_bonds[bond]` is nonzero, and is 0 (rock) while the bond holds. Throws
  // std::invalid_argument when the blocks or the bonds do not fit.
  std::vector<double> apertures(std::span<const geometry::Polygon> blocks, std::span<const dda::ContactInfo> contacts,
                                double open_threshold, std::span<const char> broken_bonds = {}) const;
  // The bond a crossing lies on, or −1 (a trace's joint).
  int bond_of(const JointCrossing& crossing) const {
    return first_bond_ >= 0 && crossing.face.fracture >= first_bond_ ? crossing.face.fracture - first_bond_ : -1;
  }

  // Per element: k_iso I plus the embedded transmissivity of every crossing in it.
  std::vector<hydro::PermeabilityTensor> permeability(std::span<const double> isotropic,
                                                      std::span<const double> apertures) const;

  // Per element: 1 where the joints replace the porosity law's open area (elements a joint
  // crosses and those sharing a node with them).
  const std::vector<char>& zone() const { return zone_; }
  const std::vector<JointCrossing>& crossings() const { return crossings_; }
  const JointApertureLaws& laws() const { return laws_; }
  // Per crossing: its law's aperture at zero stress a_r + V_m, above which it is open.
  const std::vector<double>& zero_stress_apertures() const { return zero_stress_aperture_; }

 private:
  geometry::BlockNetwork network_;
  JointApertureLaws laws_;
  std::vector<double> element_area_;
  std::vector<JointCrossing> crossings_;
  std::vector<double> zero_stress_aperture_;  // per crossing
  std::vector<double> face_length_;           // per crossing: its face's length inside the mesh
  std::vector<char> zone_;
  int first_bond_ = -1;
  int bond_count_ = 0;  // bonds with a face in the network
};

// The largest principal value of a symmetric tensor ((xx + yy)/2 + √(((xx − yy)/2)² + xy²));
// k itself for an isotropic one, bit for bit.
double largest_principal_value(const hydro::PermeabilityTensor& k);

}  // namespace hydrodda::coupling
