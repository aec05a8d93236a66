#pragma once
// The scenario as plain definition structs: what the user asked for, validated, in SI units.
// Its choices are the engines' own enums (spelled in the file as spellings.hpp says); it builds
// no engine: run/ turns these into engine inputs.

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "coupling/load_ramp.hpp"
#include "coupling/loop_acceleration.hpp"
#include "coupling/permeability_laws.hpp"
#include "dda/definitions.hpp"
#include "geometry/point.hpp"
#include "geometry/polygon.hpp"
#include "geometry/tessellation.hpp"
#include "hydro/boundary_condition.hpp"
#include "hydro/permeability_law.hpp"
#include "numerics/time_table.hpp"

namespace hydrodda::scenario {

using geometry::Point;
using geometry::Polygon;

struct Segment {
  Point from;
  Point to;
};

struct BlockDefinition {
  Polygon vertices;           // counter-clockwise
  std::string material;       // resolved: never empty after reading
  bool fixed = false;
  int line = 0;               // where it was defined, for messages
};

// The joint type a trace names (`joint = "NAME"`): empty for the default type, [joint].
struct TraceJoint {
  std::string name;
  int line = 0;  // where it is named, for messages (a fractures file's row: its line there)
};

// A generated set of parallel joints ([[geometry.joint_set]]); see geometry/joint_sets.hpp.
struct JointSetDefinition {
  double angle = 0.0;               // degrees counter-clockwise from +x
  double spacing = 0.0;             // m, along the set's normal
  double angle_spread = 0.0;        // degrees (standard deviation)
  double spacing_spread = 0.0;      // m
  std::optional<double> length;     // m, mean trace length; empty: persistent
  double length_spread = 0.0;       // m
  std::optional<double> gap;        // m, mean rock bridge along a joint; empty: the length
  double gap_spread = 0.0;          // m
  std::optional<double> offset;     // m, first joint from the region's lowest corner; empty: spacing / 2
  Polygon region;                   // empty: the domain
  std::uint64_t seed = 0;
  TraceJoint joint;
  int line = 0;
};

// A trace read from geometry.fractures_file, with its line there and its optional fifth
// column, the joint type.
struct FileFracture {
  Segment segment;
  int line = 0;
  std::string joint;
};

// Intact rock as bonded sub-blocks ([[geometry.tessellate]]): the blocks cut from the domain
// whose centroid lies in `region` are tessellated, each face between two sub-blocks a bond of
// the joint type `joint` (docs/dda.md, "Bonds").
struct TessellationDefinition {
  geometry::TessellationKind kind = geometry::TessellationKind::voronoi;
  double size = 0.0;                // m, the mean sub-block size (cells of size² on average)
  Polygon region;                   // empty: the domain
  std::uint64_t seed = 0;
  TraceJoint joint;                 // empty name: [joint]
  // Straight cracks of broken bonds inside the region: the sub-blocks conform to each (pairs of
  // seeds `size` apart mirrored across it) and the bonds along it start broken.
  std::vector<Segment> cracks;
  int cracks_line = 0;
  // Straight lines the sub-blocks' faces follow (seeded as cracks are), their bonds intact:
  // where a crack may run straight. A crack on a path takes its faces.
  std::vector<Segment> paths;
  int paths_line = 0;
  int line = 0;
};

struct GeometryDefinition {
  Polygon domain;                    // empty when blocks are given one by one
  // `fractures`, then the [[geometry.fracture]] tables, in file order.
  std::vector<Segment> fractures;
  std::vector<TraceJoint> fracture_joints;  // per entry of `fractures`: its joint type
  std::vector<JointSetDefinition> joint_sets;
  std::optional<std::filesystem::path> fractures_file;  // resolved against the scenario's folder
  std::vector<FileFracture> file_fractures;             // its rows, in order
  std::vector<Polygon> welded;
  double initial_aperture = 0.0;     // m
  int initial_aperture_line = 0;     // for messages about blocks too thin for it
  std::optional<double> min_block_area;  // m2; empty: 1% of the mean block area of the cut
  std::vector<BlockDefinition> blocks;
  std::vector<TessellationDefinition> tessellations;  // in file order; a block takes the first whose region holds it
};

// A named boundary segment; left/right/bottom/top exist by default.
struct BoundarySegment {
  std::string name;
  Segment segment;
  bool is_default = false;
};

struct MaterialDefinition {
  std::string name;
  std::optional<double> density;          // kg/m3 (mechanics)
  std::optional<double> young;            // Pa (mechanics)
  std::optional<double> poisson;          // (mechanics)
  double matrix_porosity = 0.0;
  std::optional<double> grain_diameter;   // m (Kozeny–Carman)
  // Biot's α (coupling): the blocks' faces take (1 − α) p, their skeleton the seepage force −α ∇p.
  double biot_coefficient = 1.0;
  // m²: the matrix's own permeability, fixed (flow-only runs), in place of the porosity law's.
  std::optional<double> permeability;
  // 1/Pa: the specific storage at constant strain, 1/M = φ c_f + (α − φ)/K_s (transient flow);
  // in head, S_s = ρ_w g storage (1/m).
  double storage = 0.0;
  // Materials by region: a block cut from the domain takes the material whose region holds its
  // centroid, a fluid element the one whose region holds its centroid; empty: the rest.
  Polygon region;
  int line = 0;         // the table's, for messages
  int region_line = 0;  // the region's
};

// A joint type: [joint] (the default, name empty) or [joint.NAME], whose keys default to
// [joint]'s values.
struct JointDefinition {
  std::string name;
  int line = 0;                   // the table's
  double friction_angle = 30.0;   // degrees
  double cohesion = 0.0;          // Pa
  double tensile_strength = 0.0;  // Pa
  // The joints' hydraulic aperture (docs/coupling.md, "Joint hydraulic apertures"): with any
  // of these given, joints carry a³/12 along their traces, closed or open.
  std::optional<double> residual_aperture;  // m, a closed joint's aperture (default 0)
  std::optional<double> normal_stiffness;   // k_ni, Pa/m: Barton–Bandis closure, with max_closure
  std::optional<double> max_closure;        // V_m, m
  int hydraulic_line = 0;                   // where the first of them is, for messages
  // Where a face is open to the flow: by its force (`face`, the default) or by each point's gap.
  hydro::HydraulicOpening hydraulic_opening = hydro::HydraulicOpening::face;
  // A barrier across the joint (docs/flow.md, "Joints that hinder flow"): a layer of this
  // permeability (m²) and width (m), both given or neither.
  std::optional<double> barrier_permeability;
  std::optional<double> barrier_width;
  int barrier_line = 0;
  // J/m², the energy a bond of this type takes to soften from its strength to nothing (a
  // softening bond: docs/dda.md, "Bonds"); ordinary joints of the type have no use for it.
  std::optional<double> fracture_energy;
  int fracture_energy_line = 0;
  bool hydraulic() const { return residual_aperture || normal_stiffness || max_closure; }
  bool barrier() const { return barrier_permeability && barrier_width; }
  // The barrier's resistance across it per unit area, width / permeability (m⁻¹); 0: none.
  double barrier_resistance() const { return barrier() ? *barrier_width / *barrier_permeability : 0.0; }
};

struct FixedPoint {
  Point point;
  int line = 0;
};

struct PointLoad {
  Point point;
  numerics::TimeTable force;  // N per metre of thickness: columns fx, fy (a constant or a table)
  int line = 0;
};

// A displacement prescribed on every block vertex of a boundary, or on one point.
struct PrescribedDisplacement {
  std::string boundary;          // empty when `point` is given
  std::optional<Point> point;
  Point value;                   // m, reached at ramp_time (ramped linearly) and held after
  // s of DDA time; unset: the run's duration (a coupled run's: its first pass's nominal one)
  std::optional<double> ramp_time;
  int line = 0;
};

// A distributed edge load on the block edges lying on a boundary, linear along it. Each value
// is a constant or a (time, value) table (docs/scenario.md, "Loads over time").
struct Traction {
  std::string boundary;
  numerics::TimeTable normal;      // Pa at the boundary's `from` end; compression negative
  numerics::TimeTable normal_end;  // Pa at its `to` end
  numerics::TimeTable shear;
  numerics::TimeTable shear_end;
  int line = 0;
};

struct MeasurePoint {
  std::string name;
  Point point;
  int line = 0;
};

// Every block vertex on a boundary held to it along its normal, free along it.
struct RollerDefinition {
  std::string boundary;
  int line = 0;
};

// The in-situ stress, linear in y: stress + gradient (y − reference_y), each (σxx, σyy, τxy);
// or, with vertical = "layers", integrated down through the materials' layers (run/layered_stress.hpp):
// dσyy/dy = −ρ g_y and dτxy/dy = −ρ g_x with each layer's density, σxx = stress[0] +
// horizontal_ratio (σyy − stress[1]).
struct InitialStressDefinition {
  std::array<double, 3> stress{0.0, 0.0, 0.0};    // Pa, compression negative
  double reference_y = 0.0;                        // m
  std::array<double, 3> gradient{0.0, 0.0, 0.0};  // Pa/m
  bool layers = false;                             // vertical = "layers"
  double horizontal_ratio = 0.0;                   // K0 (layers)
  std::optional<double> column_x;                  // m, the vertical the layers are read along (layers)
  int line = 0;
  int gradient_line = 0;                           // the table's when it is left out
  int vertical_line = 0;
};

// The most DDA steps a run (or a coupling pass) may take: `steps`, or end_time / time_step.
inline constexpr int kMaxSteps = 100'000'000;

struct MechanicsDefinition {
  dda::Analysis analysis = dda::Analysis::static_;
  dda::Plane plane = dda::Plane::strain;
  Point gravity{0.0, -9.81};
  double time_step = 1.0e-3;
  std::optional<int> steps;
  std::optional<double> end_time;
  // Empty: 0.01, or less where the blocks are thin against the model (run::build_mechanics_model,
  // dda::displacement_ratio_for_blocks).
  std::optional<double> max_displacement_ratio;
  dda::ContactMethod contact = dda::ContactMethod::augmented_lagrangian;
  std::optional<double> penalty;  // N/m; derived from the stiffest material when absent
  // m; empty: 1e-4 of the allowed step displacement, at most a fiftieth of the joints' a_r + V_m
  // where they carry a hydraulic aperture (run::build_mechanics_model).
  std::optional<double> penetration_tolerance;
  bool tension_cutoff = true;     // no closed contact pulls past T l (dda::Settings::tension_cutoff)
  std::vector<FixedPoint> fixed;
  std::vector<PointLoad> loads;
  std::vector<PrescribedDisplacement> displacements;
  std::vector<Traction> tractions;
  std::vector<MeasurePoint> measures;
  std::vector<RollerDefinition> rollers;
  std::optional<InitialStressDefinition> initial_stress;
};

struct FlowBoundaryCondition {
  std::string name;
  hydro::BoundaryKind kind = hydro::BoundaryKind::head;
  numerics::TimeTable value;  // m, Pa or m/s (outward normal): a constant or a (time, value) table
  int line = 0;
};

struct FlowRegion {
  std::string name;
  Polygon polygon;
  std::optional<double> permeability;  // m2: fixes k inside
  int line = 0;
};

// Transient flow ([flow.transient]): backward Euler from `initial_head` to `end_time`, the steps
// growing from `time_step` to `max_time_step` (docs/flow.md, "Transient flow").
struct TransientDefinition {
  double end_time = 0.0;                // s
  double time_step = 0.0;               // s, the first step
  double max_time_step = 0.0;           // s
  std::vector<double> output_times;     // s, increasing, in [0, end_time]; the fields' times
  std::optional<double> initial_head;   // m, everywhere; empty: "steady" (the steady heads at t = 0)
  int line = 0;
};

// A point whose head and pressure a run writes at every step (probes.csv).
struct ProbeDefinition {
  std::string name;
  Point point;
  int line = 0;
};

struct FlowDefinition {
  double fluid_density = 1000.0;   // kg/m3
  double fluid_viscosity = 1.0e-3; // Pa s
  double fluid_compressibility = 4.5e-10;  // 1/Pa (the joints' storage, when it comes: not used by the matrix's)
  hydro::PressureConvention pressure = hydro::PressureConvention::overpressure;
  coupling::PermeabilityLaw permeability_law = coupling::PermeabilityLaw::kozeny_carman;
  double permeability_cap = 9.869e-11;  // m2 (1e5 mD)
  // m2: the cubic law's cap on a fracture's permeability w²/12 (a 1 cm gap's)
  double fracture_permeability_cap = hydro::kDefaultFracturePermeabilityCap;
  std::vector<FlowBoundaryCondition> boundaries;
  std::vector<FlowRegion> regions;
  std::optional<TransientDefinition> transient;
  std::vector<ProbeDefinition> probes;
};

// A point the mesh is refined around ([[mesh.refine]]): elements of `size` there, growing
// linearly to mesh.size at `radius` (by default by a fifth of the distance).
struct MeshRefinePoint {
  Point point;
  double size = 0.0;    // m
  double radius = 0.0;  // m
};

// The default radius of a refinement of `size` in a mesh of `mesh_size`: the size grows by a
// fifth of the distance from the point, so that the triangle holding the point is about as
// large as the size at its corners, s / (1 − growth) across.
inline double default_refine_radius(double mesh_size, double size) { return (mesh_size - size) / 0.2; }

inline constexpr int kRefineTipRounds = 3;

struct MeshDefinition {
  double size = 0.0;              // m
  double fracture_size = 0.0;     // m
  double refine_distance = 0.0;   // m
  std::vector<MeshRefinePoint> refine_points;
  // A cubic-law run whose round ends with wedge tips its mesh does not resolve runs again, from
  // the blocks as built, on a mesh refined around them (docs/coupling.md, "Refined by the run");
  // at most kRefineTipRounds more rounds.
  bool refine_tips = false;
  std::optional<std::filesystem::path> file;  // resolved against the scenario's folder
  int file_line = 0;                          // line of mesh.file, for messages about it
};

struct CouplingDefinition {
  double tolerance = 1.0e-4;
  int max_iterations = 50;
  double relaxation = 1.0;
  coupling::Acceleration acceleration = coupling::Acceleration::none;
  int ramp_passes = 1;   // the fluid load raised over the first passes
  // > 1 (the reader's default for blocks in an in-situ stress): the first pass puts the load on
  // at once and, if that moves the blocks, is run again ramped over this many passes
  // (coupling::LoopSettings::ramp_if_moved).
  int ramp_if_moved = 0;
  // From still water at the lowest fixed head (overpressure) or from no fluid load (whole).
  coupling::RampedLoad ramp = coupling::RampedLoad::overpressure;
  bool settle = false;   // each pass steps on until the blocks are at rest (the reader's default: a static analysis)
  // s: each pass's flow a backward-Euler step in pseudo-time of this first step (growing by
  // SER) from the last pass's heads, with the fixed-stress split's storage; 0: steady passes
  // (coupling/pass_storage.hpp).
  double pseudo_time_step = 0.0;
};

// The ParaView series a run writes (output.fields).
struct OutputFields {
  bool fluid = true;     // fluid.pvd
  bool blocks = true;    // blocks.pvd
  bool contacts = true;  // contacts.pvd
  bool fractures = true; // fractures.pvd
};

struct OutputDefinition {
  std::filesystem::path directory;  // resolved: never empty after reading
  // Fields are written at the first and last state and every `every` passes or steps. 100, so
  // that a mechanics run of thousands of steps writes tens of files, not thousands, and a
  // coupled run of up to 100 passes its first and last.
  int every = 100;
  OutputFields fields;
  std::vector<std::string> figures{"png"};
};

// A default the reader filled in, for the log.
struct DefaultUsed {
  std::string key;
  std::string value;
};

struct Scenario {
  std::filesystem::path file;
  std::string title;
  std::optional<GeometryDefinition> geometry;
  std::vector<BoundarySegment> boundaries;
  std::vector<MaterialDefinition> materials;  // in file order
  JointDefinition joint;                   // the default type, [joint]
  std::vector<JointDefinition> joint_types;  // [joint.NAME], by name
  std::optional<MechanicsDefinition> mechanics;
  std::optional<FlowDefinition> flow;
  std::optional<MeshDefinition> mesh;
  CouplingDefinition coupling;
  OutputDefinition output;
  std::vector<DefaultUsed> defaults_used;

  const BoundarySegment* find_boundary(std::string_view name) const;
  const MaterialDefinition* find_material(std::string_view name) const;
  // The joint type of a trace: 0 for [joint], i + 1 for joint_types[i]; -1 for a name that
  // names none (refused by the reader).
  int joint_type_index(std::string_view name) const;
  // Type `index` as joint_type_index numbers them.
  const JointDefinition& joint_type(int index) const { return index == 0 ? joint : joint_types.at(index - 1); }
  int joint_type_count() const { return 1 + static_cast<int>(joint_types.size()); }
  bool any_joint_hydraulic() const;
  bool any_joint_barrier() const;
};

}  // namespace hydrodda::scenario
