#pragma once
// Plain definition structs the DDA engine is built from: blocks, materials, joints, settings,
// loads. No scenario or output types: the scenario reader and the coupling loop fill these.

#include <array>
#include <optional>
#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"
#include "numerics/time_table.hpp"

namespace hydrodda::dda {

using geometry::Point;
using geometry::Polygon;

struct Material {
  double density = 2500.0;  // kg/m3
  double young = 1.0e10;    // Pa
  double poisson = 0.25;
};

// Mohr–Coulomb joint: shear strength c·l + N tan φ; tension up to tensile_strength·l.
struct Joint {
  double friction_angle_deg = 30.0;
  double cohesion = 0.0;          // Pa
  double tensile_strength = 0.0;  // Pa
  // J/m2, G_f; > 0 on a bond's type: the bond softens in tension over G_f instead of breaking
  // at T (a cohesive traction T (1 − w/w_c), w_c = 2 G_f / T; docs/dda.md, "Bonds").
  double fracture_energy = 0.0;
};

struct BlockDefinition {
  Polygon polygon;  // simple, counter-clockwise, no repeated closing vertex
  int material = 0;
  bool fixed = false;
  // Per edge (vertex k → k + 1): the joint type of the contacts against it (0: `joint`, i:
  // joint_types[i − 1]); empty: 0 for every edge.
  std::vector<int> edge_joints;
  std::array<double, 3> initial_stress{0.0, 0.0, 0.0};    // σxx, σyy, τxy (Pa)
  std::array<double, 3> initial_velocity{0.0, 0.0, 0.0};  // vx, vy (m/s), ω (rad/s)
  // Per edge: the bond (intact rock) it shares with an edge of a neighbouring sub-block, the
  // same id on both sides, or −1; empty: no bonded edge. A bonded face carries tension up to
  // its joint type's tensile_strength and shear up to c + σn tan φ; once it fails it is a
  // joint of that type with neither tension nor cohesion (docs/dda.md, "Bonds"). −2 − k: zone
  // face k, a face within a Voronoi cell zoned into triangles (UDEC's deformable Voronoi
  // blocks), locked as a bond's face and never broken; not among System::bond_count().
  std::vector<int> edge_bonds{};
};

enum class Analysis { static_, dynamic };
enum class Plane { strain, stress };
enum class ContactMethod { augmented_lagrangian, penalty };

struct Settings {
  Analysis analysis = Analysis::static_;
  Plane plane = Plane::strain;
  Point gravity{0.0, -9.81};
  double time_step = 1.0e-3;              // s, the largest step taken
  double max_displacement_ratio = 0.01;   // allowed step displacement ÷ half the model height
  ContactMethod contact = ContactMethod::augmented_lagrangian;
  double penalty = 0.0;                   // N/m; 0 → 50 × the largest Young's modulus × 1 m
  double penetration_tolerance = 0.0;     // m; 0 → 1e-4 × allowed step displacement
  double contact_distance = 0.0;          // m; 0 → 2.5 × allowed step displacement
  // m; the margin the contact search lists pairs and vertex–edge combinations with, kept
  // until a vertex has moved half of it (contact_search.hpp); < 0 → a fifth of the contact
  // distance; 0 → made afresh every step. The contacts found do not depend on it.
  double contact_skin = -1.0;
  // true: no closed contact ends a step pulling harder than T l, to 1e-9 of the largest
  // normal force (docs/dda.md, Open–close iteration); false: the hysteresis band lets it pull
  // up to T l + p × 1% (10% when chattering) of the penetration tolerance. Not the default
  // yet: see docs/dda.md, Known limits.
  bool tension_cutoff = false;
  int max_open_close_iterations = 12;     // then the step is cut and retried
  int max_lagrangian_iterations = 30;
  double static_tolerance = 1.0e-9;       // run_to_equilibrium: max step displacement ÷ model size
  // At rest also: no block's unbalanced force (the step's inertial force 2 m |d|/Δt²) above
  // this share of the forces on it (1e-5: Itasca's UDEC/3DEC local force ratio limit); 0: not
  // tested. Not the default yet: see docs/dda.md, "At rest".
  double unbalanced_force_tolerance = 0.0;
};

// A material point of a block held in place (a stiff spring to its initial position).
struct FixedPoint {
  int block = 0;
  Point point;
};

// A force (N per metre of thickness) at a material point, fixed in direction: a table of two
// columns (fx, fy), constant or read at the load time (System::hold_load_time).
struct PointLoad {
  int block = 0;
  Point point;
  numerics::TimeTable force;
};

inline numerics::TimeTable constant_force(Point force) {
  const double values[2]{force.x, force.y};
  return numerics::TimeTable::constant(values);
}

// A material point driven to initial position + value, ramped linearly to reach it at
// ramp_time (the run's end time) and held after.
struct PrescribedDisplacement {
  int block = 0;
  Point point;
  Point value;
  double ramp_time = 1.0;
  int entry = 0;  // the definition it came from (a boundary gives a point per vertex on it)
};

// Traction on edge `edge` (from vertex edge to edge+1) varying linearly from its first to its
// second vertex. Normal positive = tension (along the outward normal); shear along the edge.
// Each value (Pa) is constant or a table read at the load time (System::hold_load_time).
struct EdgeTraction {
  int block = 0;
  int edge = 0;
  numerics::TimeTable normal_start;
  numerics::TimeTable normal_end;
  numerics::TimeTable shear_start;
  numerics::TimeTable shear_end;
};

struct MeasuredPoint {
  int block = 0;
  Point point;
};

// A block vertex held on a straight boundary: its displacement along `normal` is held at zero
// by a stiff spring along the normal only (10 × the contact penalty, as a fixed point's), and
// it slides freely along the boundary.
struct Roller {
  int block = 0;
  int vertex = 0;
  Point normal;          // unit, out of the model
  double preload = 0.0;  // N/m: the force the boundary pushes the vertex in with from the start
                         // (the initial stress's share on the vertex's faces along it)
  // The vertex's neighbours (previous, next) whose faces with it lie along the boundary.
  std::array<bool, 2> faces_along{};
};

// A value of a layered stress field: σ at height y.
struct StressKnot {
  double y = 0.0;                              // m
  std::array<double, 3> stress{0.0, 0.0, 0.0};  // Pa
};

// A stress field linear in y, as UDEC's insitu with ygradient: σ(y) = at_reference +
// gradient (y − reference_y), components (σxx, σyy, τxy), Pa, compression negative. With
// `knots` (two or more, y increasing), it is piecewise linear in y instead: linear between
// knots, and beyond the end knots along the end pieces (a layered model's, each layer's
// gradient from its density).
struct StressField {
  std::array<double, 3> at_reference{0.0, 0.0, 0.0};
  double reference_y = 0.0;                           // m
  std::array<double, 3> gradient{0.0, 0.0, 0.0};      // Pa/m
  std::vector<StressKnot> knots;
  std::array<double, 3> at(double y) const {
    if (knots.size() >= 2) return interpolate_knots(y);
    const double dy = y - reference_y;
    return {at_reference[0] + gradient[0] * dy, at_reference[1] + gradient[1] * dy,
            at_reference[2] + gradient[2] * dy};
  }

 private:
  std::array<double, 3> interpolate_knots(double y) const {
    std::size_t k = 1;  // the piece [knots[k − 1], knots[k]] that holds y, or the end one nearest
    while (k + 1 < knots.size() && y > knots[k].y) ++k;
    const StressKnot& a = knots[k - 1];
    const StressKnot& b = knots[k];
    const double t = (y - a.y) / (b.y - a.y);
    return {a.stress[0] + t * (b.stress[0] - a.stress[0]), a.stress[1] + t * (b.stress[1] - a.stress[1]),
            a.stress[2] + t * (b.stress[2] - a.stress[2])};
  }
};

// Everything the engine is built from.
struct ModelDefinition {
  std::vector<BlockDefinition> blocks;
  std::vector<Material> materials;
  Joint joint;                    // type 0, the default
  std::vector<Joint> joint_types; // types 1, 2, ...: a contact takes the type of its edge
  Settings settings;
  std::vector<FixedPoint> fixed_points;
  std::vector<PointLoad> point_loads;
  std::vector<PrescribedDisplacement> displacements;
  std::vector<EdgeTraction> tractions;
  std::vector<MeasuredPoint> measured_points;
  std::vector<Roller> rollers;
  // The in-situ stress: each block starts with it at its centroid (added to its own
  // initial_stress), and the contacts that touch at the start carry it (initial_stress.hpp).
  std::optional<StressField> initial_stress;
  // Bonds (BlockDefinition::edge_bonds) that start broken: a crack of intact rock's faces, a
  // joint from the start (docs/dda.md, "Bonds"). Not breaks of the run: never in bond_breaks().
  std::vector<int> broken_bonds;
};

}  // namespace hydrodda::dda
