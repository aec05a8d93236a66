#pragma once
// From a validated scenario to engine inputs. Problems only visible once the model is built
// (a fixed point in no block, a boundary that touches no block) are input errors: they are
// thrown as a ScenarioError naming the file, line and key, like the reader's.

#include <span>
#include <string>
#include <vector>

#include "coupling/joint_aperture_laws.hpp"
#include "coupling/permeability_model.hpp"
#include "dda/definitions.hpp"
#include "hydro/darcy_solver.hpp"
#include "mesh/mesh_request.hpp"
#include "hydro/permeability_law.hpp"
#include "mesh/triangle_mesh.hpp"
#include "run/model_geometry.hpp"

#include <filesystem>
#include <optional>

#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Whether the cut's warnings are logged as warnings, or only at debug level: a run that cuts
// the same domain again (a later round of mesh.refine_tips) has said them once.
enum class GeometryWarnings { logged, already_logged };

// The scenario's domain cut into blocks (model_geometry.hpp), its warnings and summary logged.
ModelGeometry build_and_log_geometry(const scenario::Scenario& scenario,
                                     GeometryWarnings warnings = GeometryWarnings::logged);

// The blocks of a cut domain, free, each of the material whose region holds its centroid (the
// one without a region elsewhere); a block in no material is a ScenarioError naming `material`.
std::vector<dda::BlockDefinition> blocks_of(const scenario::Scenario& scenario, const ModelGeometry& model);

// The block polygons of the scenario (counter-clockwise), with their material index and
// fixed flag, in the order the scenario defines them.
std::vector<dda::BlockDefinition> build_blocks(const scenario::Scenario& scenario,
                                               GeometryWarnings warnings = GeometryWarnings::logged);

// The default contact penetration tolerance where the joints carry a hydraulic aperture, as a
// fraction of their aperture at zero stress a_r + V_m, the smallest of the joint types' (when
// that is below the DDA's own default).
inline constexpr double kJointApertureResolution = 0.02;

// The DDA model: blocks, materials, joint, settings and every load of [mechanics].
dda::ModelDefinition build_mechanics_model(const scenario::Scenario& scenario,
                                           std::vector<dda::BlockDefinition> blocks);

// The edge loads of the scenario's [[mechanics.traction]] on the blocks as built (initial
// positions); throws a ScenarioError for a boundary on which no block edge lies.
std::vector<dda::EdgeTraction> build_tractions(const scenario::Scenario& scenario,
                                               const std::vector<dda::BlockDefinition>& blocks);
// The permeability law of [flow] with the porosity and grain size of the material without a
// region (the only one in a model without regions).
// A joint type's hydraulic aperture law (all zero when it gives none, nor [joint] for it to
// inherit: an open joint then has its opening, a closed one nothing).
hydro::JointApertureLaw make_joint_aperture_law(const scenario::JointDefinition& joint);
// Each trace's law, its joint type's (`traces` by fracture id, as the geometry made them).
coupling::JointApertureLaws make_joint_aperture_laws(const scenario::Scenario& scenario,
                                                     std::span<const geometry::FractureTrace> traces);
// The smallest aperture at zero stress a_r + V_m above zero of the joint types ([joint] and
// every [joint.NAME]); 0 when none has one. The default penetration tolerance resolves it.
double smallest_joint_zero_stress_aperture(const scenario::Scenario& scenario);
coupling::PermeabilityModel make_permeability_model(const scenario::Scenario& scenario);
// Under Kozeny–Carman, where flow.permeability_cap lowers the matrix's own permeability: a
// warning naming the first material (of those the law maps: the one without a region first) whose
// matrix it caps, its value and the key; none otherwise (the cubic law's matrix
// is never capped).
std::optional<std::string> describe_capped_matrix(const scenario::Scenario& scenario);

// Per block, the Biot coefficient of its material.
std::vector<double> find_biot_coefficients(const scenario::Scenario& scenario,
                                           const std::vector<dda::BlockDefinition>& blocks);

// The user's mesh.file, read; a file Gmsh cannot read or without triangles is a ScenarioError
// naming the mesh.file line, and a flow boundary the file does not name, one naming its line.
mesh::TriangleMesh read_mesh_file(const scenario::Scenario& scenario);

// What Gmsh is asked to mesh: the domain, its named boundaries, the fracture traces to refine
// along, the flow regions and the [mesh] sizes (a scenario without mesh.file).
mesh::MeshRequest make_mesh_request(const scenario::Scenario& scenario);

// The fixed fluid mesh: generated with Gmsh (refined along the fractures, honouring the flow
// regions) or read from mesh.file. With `mesh_cache`, a generated mesh is taken from that
// folder when a run with the same request has left it there, else left there (mesh_cache.hpp).
mesh::TriangleMesh build_mesh(const scenario::Scenario& scenario,
                              const std::optional<std::filesystem::path>& mesh_cache = std::nullopt);

// Triangles whose centroid lies in the polygon: the mesh honours region boundaries, so this is
// exact, and overlapping regions each keep all of their triangles.
std::vector<int> select_triangles_in(const mesh::TriangleMesh& mesh, const geometry::Polygon& polygon);

// Per triangle, the material (index) whose region holds its centroid, else the one without a
// region; -1 where none does.
std::vector<int> find_element_materials(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh);

// make_permeability_model with, where materials differ by region, each element's matrix
// porosity and grain diameter.
coupling::PermeabilityModel make_element_permeability_model(const scenario::Scenario& scenario,
                                                            const mesh::TriangleMesh& mesh);

// Per element, the permeability a [[flow.region]] fixes (the last listed wins), else its
// material's `permeability`; a joint barrier's strip over either; or none.
std::vector<std::optional<double>> find_fixed_permeability(const scenario::Scenario& scenario,
                                                           const mesh::TriangleMesh& mesh);
// Its two parts: what regions and barrier strips impose (a joint's transmissivity does not
// add to these), and the materials' own matrix `permeability` (to which it does).
std::vector<std::optional<double>> find_imposed_permeability(const scenario::Scenario& scenario,
                                                             const mesh::TriangleMesh& mesh);
std::vector<std::optional<double>> find_material_permeability(const scenario::Scenario& scenario,
                                                              const mesh::TriangleMesh& mesh);

// k per triangle of the unfractured case: intact rock of the matrix porosity everywhere
// (k_m = Kozeny–Carman of φ_m, which both laws give where no fracture area lies), except where
// a flow region fixes the permeability.
std::vector<double> compute_matrix_permeability(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh);

// The flow problem with its boundary values at `load_time` (tables read there; constants are
// the same at any time).
hydro::DarcyProblem build_flow_problem(const scenario::FlowDefinition& flow, double load_time);

// Total simulated time of a mechanics run: end_time, or steps × time_step.
double mechanics_duration(const scenario::MechanicsDefinition& mechanics);

}  // namespace hydrodda::run
