#include "scenario/reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "scenario/bounds.hpp"
#include "scenario/fracture_sources.hpp"
#include "scenario/tessellations.hpp"
#include "scenario/input_files.hpp"
#include "scenario/rollers_and_initial_stress.hpp"
#include "scenario/table_view.hpp"
#include "scenario/transient_reading.hpp"
#include "scenario/validation.hpp"

namespace hydrodda::scenario {

const BoundarySegment* Scenario::find_boundary(std::string_view name) const {
  for (const BoundarySegment& b : boundaries)
    if (b.name == name) return &b;
  return nullptr;
}

const MaterialDefinition* Scenario::find_material(std::string_view name) const {
  for (const MaterialDefinition& m : materials)
    if (m.name == name) return &m;
  return nullptr;
}

int Scenario::joint_type_index(std::string_view name) const {
  if (name.empty()) return 0;
  for (std::size_t i = 0; i < joint_types.size(); ++i)
    if (joint_types[i].name == name) return static_cast<int>(i) + 1;
  return -1;
}

bool Scenario::any_joint_hydraulic() const {
  return joint.hydraulic() ||
         std::any_of(joint_types.begin(), joint_types.end(), [](const JointDefinition& j) { return j.hydraulic(); });
}

bool Scenario::any_joint_barrier() const {
  return joint.barrier() ||
         std::any_of(joint_types.begin(), joint_types.end(), [](const JointDefinition& j) { return j.barrier(); });
}

namespace {

// A straight cut of the domain, `from` its file position: `key` names it in messages.
bool check_fracture_trace(ReadContext& ctx, int line, const std::string& key, const Polygon& points,
                          const Polygon& domain) {
  if (points.size() != 2) {
    ctx.error(line, key, "a fracture is a straight cut: two points [[x1, y1], [x2, y2]]");
    return false;
  }
  if (points[0] == points[1]) {
    ctx.error(line, key, "a fracture's two end points coincide");
    return false;
  }
  if (!segment_meets_polygon(points[0], points[1], domain)) {
    ctx.error(line, key, "the fracture lies wholly outside the domain");
    return false;
  }
  return true;
}

// [[geometry.fracture]]: one trace with its joint type, after the `fractures` list.
void read_fracture_tables(ReadContext& ctx, const TableView& g, GeometryDefinition& geometry) {
  for (const toml::table* table : g.tables("fracture")) {
    const TableView f(ctx, *table, "geometry.fracture", {"trace", "joint"});
    TraceJoint joint;
    if (auto name = f.string("joint")) joint = {*name, f.line_of_key("joint")};
    if (!f.has("trace")) {
      ctx.error(f.line(), "geometry.fracture.trace", "required key is missing");
      continue;
    }
    const auto points = f.points("trace");
    if (!points || !check_fracture_trace(ctx, f.line_of_key("trace"), "geometry.fracture.trace", *points, geometry.domain))
      continue;
    geometry.fractures.push_back({(*points)[0], (*points)[1]});
    geometry.fracture_joints.push_back(std::move(joint));
  }
}

void read_geometry(ReadContext& ctx, const TableView& root, Scenario& s) {
  const toml::table* t = root.table("geometry");
  if (!t) return;
  const TableView g(ctx, *t, "geometry",
                    {"domain", "fractures", "fracture", "welded", "initial_aperture", "block", "joint_set",
                     "fractures_file", "min_block_area", "tessellate"});
  GeometryDefinition geometry;
  if (auto domain = g.points("domain")) {
    geometry.domain = std::move(*domain);
    check_polygon(ctx, g.line_of_key("domain"), "geometry.domain", geometry.domain);
  }
  for (auto& [line_points, line] : g.point_lists("fractures")) {
    if (!check_fracture_trace(ctx, line, "geometry.fractures", line_points, geometry.domain)) continue;
    geometry.fractures.push_back({line_points[0], line_points[1]});
    geometry.fracture_joints.push_back({});
  }
  read_fracture_tables(ctx, g, geometry);
  read_joint_sets(ctx, g, geometry);
  read_fractures_file(ctx, g, s.file, geometry);
  read_tessellations(ctx, g, geometry);
  const bool has_traces = !geometry.fractures.empty() || !geometry.joint_sets.empty() || !geometry.file_fractures.empty();
  if (auto area = g.number("min_block_area")) {
    geometry.min_block_area = *area;
    g.require("min_block_area", *area > 0.0, "must be > 0");
  }
  for (auto& [polygon, line] : g.point_lists("welded")) {
    if (check_polygon(ctx, line, "geometry.welded", polygon) && geometry.domain.size() >= 3 &&
        !polygons_overlap(polygon, geometry.domain))
      ctx.error(line, "geometry.welded", "the welded region lies wholly outside geometry.domain");
    geometry.welded.push_back(std::move(polygon));
  }
  if (g.has("initial_aperture")) {
    geometry.initial_aperture = g.number("initial_aperture").value_or(0.0);
    g.require("initial_aperture", geometry.initial_aperture >= 0.0, "must be >= 0");
  } else if (has_traces) {
    geometry.initial_aperture = g.number_or("initial_aperture", 0.0);
  }
  geometry.initial_aperture_line = g.line_of_key("initial_aperture");
  for (const toml::table* bt : g.tables("block")) {
    const TableView b(ctx, *bt, "geometry.block", {"vertices", "material", "fixed"});
    BlockDefinition block;
    block.line = b.line();
    if (auto v = b.points("vertices")) {
      block.vertices = std::move(*v);
      check_polygon(ctx, b.line_of_key("vertices"), "geometry.block.vertices", block.vertices);
    } else if (!b.has("vertices")) {
      ctx.error(b.line(), "geometry.block.vertices", "required key is missing");
    }
    block.material = b.string("material").value_or("");
    block.fixed = b.boolean("fixed").value_or(false);
    geometry.blocks.push_back(std::move(block));
  }
  if (geometry.domain.empty() && geometry.blocks.empty())
    ctx.error(g.line(), "geometry", "give a domain (cut by fractures) or blocks ([[geometry.block]])");
  if (!geometry.domain.empty() && !geometry.blocks.empty())
    ctx.error(g.line(), "geometry.block",
              "give either a domain cut by fractures or blocks one by one, not both");
  if (geometry.domain.empty() && (has_traces || !geometry.welded.empty()))
    ctx.error(g.line(), "geometry.domain", "fractures, joint sets and welded regions need a domain to cut");
  s.geometry = std::move(geometry);
}

void add_default_boundaries(Scenario& s) {
  geometry::Box box;
  if (s.geometry) {
    for (Point p : s.geometry->domain) box.add(p);
    for (const BlockDefinition& b : s.geometry->blocks)
      for (Point p : b.vertices) box.add(p);
  }
  if (box.empty()) return;
  const Point ll = box.lo, ur = box.hi;
  const Point lr{ur.x, ll.y}, ul{ll.x, ur.y};
  // Each runs in the direction of increasing coordinate: a traction's `normal` applies at
  // `from`, `normal_end` at `to`.
  s.boundaries.push_back({"left", {ll, ul}, true});
  s.boundaries.push_back({"right", {lr, ur}, true});
  s.boundaries.push_back({"bottom", {ll, lr}, true});
  s.boundaries.push_back({"top", {ul, ur}, true});
}

void read_boundaries(ReadContext& ctx, const TableView& root, Scenario& s) {
  add_default_boundaries(s);
  const toml::table* t = root.table("boundaries");
  if (!t) return;
  for (auto&& [key, value] : *t) {
    const std::string name{key.str()};
    const std::string path = "boundaries." + name;
    const toml::table* segment = value.as_table();
    if (!segment) {
      ctx.error(line_of(value), path, "expected { from = [x, y], to = [x, y] }");
      continue;
    }
    const TableView b(ctx, *segment, path, {"from", "to"});
    const auto from = b.point("from");
    const auto to = b.point("to");
    if (!b.has("from")) ctx.error(b.line(), path + ".from", "required key is missing");
    if (!b.has("to")) ctx.error(b.line(), path + ".to", "required key is missing");
    if (!from || !to) continue;
    if (*from == *to)  // still declared, so that references to it raise no second error
      ctx.error(b.line(), path, "'from' and 'to' coincide: a boundary segment needs length");
    BoundarySegment boundary{name, {*from, *to}, false};
    auto existing = std::find_if(s.boundaries.begin(), s.boundaries.end(),
                                 [&](const BoundarySegment& x) { return x.name == name; });
    if (existing != s.boundaries.end()) *existing = boundary;  // a user may redefine a default
    else s.boundaries.push_back(boundary);
  }
}

void read_materials(ReadContext& ctx, const TableView& root, Scenario& s) {
  const toml::table* t = root.table("material");
  if (!t) return;
  for (auto&& [key, value] : *t) {
    const std::string name{key.str()};
    const std::string path = "material." + name;
    const toml::table* mt = value.as_table();
    if (!mt) {
      ctx.error(line_of(value), path, "expected a table [material." + name + "]");
      continue;
    }
    const TableView m(ctx, *mt, path,
                      {"density", "young", "poisson", "matrix_porosity", "grain_diameter", "biot_coefficient",
                       "permeability", "region", "storage"});
    MaterialDefinition material;
    material.name = name;
    material.line = m.line();
    if (auto region = m.points("region")) {
      material.region_line = m.line_of_key("region");
      if (check_polygon(ctx, material.region_line, path + ".region", *region)) material.region = std::move(*region);
    }
    if (auto k = m.number("permeability")) {
      material.permeability = *k;
      m.require("permeability", *k > 0.0 && *k <= kMaxPermeability,
                fmt::format("must lie in (0, {:g}] m²: beyond, pores are some 10 cm across and the flow is not Darcy's",
                            kMaxPermeability));
    }
    material.density = m.number("density");
    material.young = m.number("young");
    material.poisson = m.number("poisson");
    material.grain_diameter = m.number("grain_diameter");
    if (material.density) m.require("density", *material.density > 0.0, "must be > 0");
    if (material.young) {
      m.require("young", *material.young > 0.0, "must be > 0");
      m.require("young", !(*material.young > 0.0) || (*material.young >= kMinYoung && *material.young <= kMaxYoung),
                fmt::format("must lie in [{:g}, {:g}] Pa: from softer than any soil to ten times diamond's", kMinYoung,
                            kMaxYoung));
    }
    if (material.poisson)
      m.require("poisson", *material.poisson > -1.0 && *material.poisson < 0.5,
                "must lie in (-1, 0.5)");
    if (material.grain_diameter)
      m.require("grain_diameter", *material.grain_diameter >= kMinGrainDiameter && *material.grain_diameter <= kMaxGrainDiameter,
                fmt::format("must lie in [{:g}, {:g}] m: from a tenth of the finest clay platelet to a boulder",
                            kMinGrainDiameter, kMaxGrainDiameter));
    if (m.has("matrix_porosity")) {
      material.matrix_porosity = m.number("matrix_porosity").value_or(0.0);
      m.require("matrix_porosity",
                material.matrix_porosity >= 0.0 && material.matrix_porosity < 1.0,
                "must lie in [0, 1)");
    }
    material.biot_coefficient = m.number_or("biot_coefficient", material.biot_coefficient);
    m.require("biot_coefficient", material.biot_coefficient >= 0.0 && material.biot_coefficient <= 1.0,
              "must lie in [0, 1]");
    material.storage = m.number("storage").value_or(0.0);
    m.require("storage", material.storage >= 0.0 && material.storage <= kMaxStorage,
              fmt::format("must lie in [0, {:g}] 1/Pa: the specific storage of the softest clay is some 1e-7 1/Pa",
                          kMaxStorage));
    s.materials.push_back(std::move(material));
  }
}

const std::vector<std::string> kJointKeys{"friction_angle",    "cohesion",         "tensile_strength",
                                          "residual_aperture", "normal_stiffness", "max_closure",
                                          "barrier_permeability", "barrier_width", "fracture_energy",
                                          "hydraulic_opening"};

// The keys of one joint type over `joint` (the default type's values, or the built-in ones).
void read_joint_keys(ReadContext& ctx, const TableView& j, JointDefinition& joint) {
  joint.line = j.line();
  joint.friction_angle = j.number_or("friction_angle", joint.friction_angle);
  joint.cohesion = j.number_or("cohesion", joint.cohesion);
  joint.tensile_strength = j.number_or("tensile_strength", joint.tensile_strength);
  j.require("friction_angle", joint.friction_angle >= 0.0 && joint.friction_angle < 90.0,
            "must lie in [0, 90) degrees");
  j.require("cohesion", joint.cohesion >= 0.0, "must be >= 0");
  j.require("tensile_strength", joint.tensile_strength >= 0.0, "must be >= 0");
  if (j.has("residual_aperture")) joint.residual_aperture = j.number("residual_aperture");
  if (j.has("normal_stiffness")) joint.normal_stiffness = j.number("normal_stiffness");
  if (j.has("max_closure")) joint.max_closure = j.number("max_closure");
  for (const char* key : {"residual_aperture", "normal_stiffness", "max_closure"})
    if (j.has(key)) {
      joint.hydraulic_line = j.line_of_key(key);
      break;
    }
  // A default worth listing only where the joints conduct by a law of their own.
  if (j.has("hydraulic_opening") || joint.hydraulic())
    joint.hydraulic_opening = j.choice("hydraulic_opening", joint.hydraulic_opening);
  if (j.has("residual_aperture") && joint.residual_aperture)
    j.require("residual_aperture", *joint.residual_aperture >= 0.0 && *joint.residual_aperture < 1.0,
              "must lie in [0, 1) m");
  if (j.has("normal_stiffness") && joint.normal_stiffness)
    j.require("normal_stiffness", *joint.normal_stiffness > 0.0, "must be > 0 (Pa/m)");
  if (j.has("max_closure") && joint.max_closure)
    j.require("max_closure", *joint.max_closure > 0.0 && *joint.max_closure < 1.0, "must lie in (0, 1) m");
  // The Barton–Bandis closure needs both its stiffness and its largest closure.
  if (joint.normal_stiffness && !joint.max_closure)
    ctx.error(j.line_of_key("normal_stiffness"), j.key_path("max_closure"), "required with " + j.key_path("normal_stiffness"));
  if (joint.max_closure && !joint.normal_stiffness)
    ctx.error(j.line_of_key("max_closure"), j.key_path("normal_stiffness"), "required with " + j.key_path("max_closure"));
  // A barrier is a layer: its permeability and its width, both or neither.
  if (j.has("barrier_permeability")) joint.barrier_permeability = j.number("barrier_permeability");
  if (j.has("barrier_width")) joint.barrier_width = j.number("barrier_width");
  for (const char* key : {"barrier_permeability", "barrier_width"})
    if (j.has(key)) {
      joint.barrier_line = j.line_of_key(key);
      break;
    }
  if (j.has("barrier_permeability") && joint.barrier_permeability)
    j.require("barrier_permeability", *joint.barrier_permeability > 0.0, "must be > 0 (m2)");
  if (j.has("barrier_width") && joint.barrier_width)
    j.require("barrier_width", *joint.barrier_width > 0.0 && *joint.barrier_width < 1.0, "must lie in (0, 1) m");
  if (joint.barrier_permeability && !joint.barrier_width)
    ctx.error(joint.barrier_line, j.key_path("barrier_width"), "required with barrier_permeability");
  if (joint.barrier_width && !joint.barrier_permeability)
    ctx.error(joint.barrier_line, j.key_path("barrier_permeability"), "required with barrier_width");
  if (j.has("fracture_energy")) {
    joint.fracture_energy = j.number("fracture_energy");
    joint.fracture_energy_line = j.line_of_key("fracture_energy");
    if (joint.fracture_energy) j.require("fracture_energy", *joint.fracture_energy >= 0.0, "must be >= 0 (J/m2)");
  }
}

// [joint], the default type, and its sub-tables [joint.NAME], each a type whose keys default
// to [joint]'s values.
void read_joint(ReadContext& ctx, const TableView& root, Scenario& s) {
  const toml::table* t = root.table("joint");
  if (!t) return;
  std::vector<std::string> allowed = kJointKeys;
  std::vector<std::pair<std::string, const toml::table*>> named;
  for (auto&& [key, value] : *t)
    if (const toml::table* sub = value.as_table()) {
      named.emplace_back(std::string(key.str()), sub);
      allowed.emplace_back(key.str());
    }
  const TableView j(ctx, *t, "joint", allowed);
  read_joint_keys(ctx, j, s.joint);
  for (const auto& [name, table] : named) {
    const TableView type(ctx, *table, "joint." + name, kJointKeys);
    JointDefinition joint = s.joint;
    joint.name = name;
    read_joint_keys(ctx, type, joint);
    s.joint_types.push_back(std::move(joint));
  }
}

void read_mechanics(ReadContext& ctx, const TableView& root, Scenario& s) {
  const toml::table* t = root.table("mechanics");
  if (!t) return;
  const TableView m(ctx, *t, "mechanics",
                    {"analysis", "plane", "gravity", "time_step", "steps", "end_time",
                     "max_displacement_ratio", "contact", "penalty", "penetration_tolerance", "tension_cutoff",
                     "fixed", "load", "displacement", "traction", "measure", "roller", "initial_stress"});
  MechanicsDefinition mech;
  mech.analysis = m.choice("analysis", dda::Analysis::static_);
  mech.plane = m.choice("plane", dda::Plane::strain);
  if (auto g = m.point("gravity")) mech.gravity = *g;
  else if (!m.has("gravity")) ctx.defaults.push_back({"mechanics.gravity", "[0, -9.81]"});
  mech.time_step = m.number_or("time_step", mech.time_step);
  m.require("time_step", mech.time_step > 0.0, "must be > 0");
  // A bad value is recorded as an error; 1 keeps 'steps' and 'end_time' exclusive meanwhile.
  if (m.has("steps")) mech.steps = m.integer("steps", 1, kMaxSteps).value_or(1);
  if (auto end = m.number("end_time")) {
    mech.end_time = *end;
    m.require("end_time", *end > 0.0, "must be > 0");
    if (*end > 0.0 && mech.time_step > 0.0 && *end / mech.time_step > kMaxSteps)
      m.require("end_time", false,
                fmt::format("end_time / time_step = {} steps; at most {} (a larger time_step, or a shorter end_time)",
                            format_number(*end / mech.time_step), kMaxSteps));
  }
  if (mech.steps && mech.end_time)
    ctx.error(m.line_of_key("end_time"), "mechanics.end_time", "give 'steps' or 'end_time', not both");
  if (!mech.steps && !mech.end_time) {
    mech.steps = 100;
    ctx.defaults.push_back({"mechanics.steps", "100"});
  }
  // Its default depends on the blocks: it is made, and reported, where they are built.
  if (auto r = m.number("max_displacement_ratio")) {
    mech.max_displacement_ratio = *r;
    m.require("max_displacement_ratio", *r > 0.0 && *r <= 1.0, "must lie in (0, 1]");
    m.require("max_displacement_ratio", !(*r > 0.0) || *r >= kMinDisplacementRatio,
              fmt::format("must be at least {:g}: a step's displacement below it is lost in the positions' round-off",
                          kMinDisplacementRatio));
  }
  mech.contact = m.choice("contact", dda::ContactMethod::augmented_lagrangian);
  if (auto p = m.number("penalty")) {
    mech.penalty = *p;
    m.require("penalty", *p > 0.0, "must be > 0");
    double stiffest = 0.0;
    for (const MaterialDefinition& material : s.materials) stiffest = std::max(stiffest, material.young.value_or(0.0));
    if (*p > 0.0 && stiffest > 0.0)
      m.require("penalty", *p <= kMaxPenaltyPerYoung * stiffest,
                fmt::format("must be at most {:g} N/m, {:g} times the stiffest material's Young's modulus × 1 m (the "
                            "default is 50 times): stiffer contacts hold nothing more and overflow the stiffness matrix",
                            kMaxPenaltyPerYoung * stiffest, kMaxPenaltyPerYoung));
  }
  // Its default depends on the blocks and the joints: made, and reported, where they are built.
  if (auto t = m.number("penetration_tolerance")) {
    mech.penetration_tolerance = *t;
    m.require("penetration_tolerance", *t > 0.0, "must be > 0");
    const geometry::Box box = find_model_box(s);
    const double size = box.empty() ? 0.0 : std::max(box.width(), box.height());
    if (*t > 0.0 && size > 0.0)
      m.require("penetration_tolerance", *t >= kMinPenetrationPerSize * size,
                fmt::format("must be at least {:g} m, {:g} of the model's size: positions do not resolve less",
                            kMinPenetrationPerSize * size, kMinPenetrationPerSize));
  }
  mech.tension_cutoff = m.boolean("tension_cutoff").value_or(true);

  for (const toml::table* ft : m.tables("fixed")) {
    const TableView f(ctx, *ft, "mechanics.fixed", {"point"});
    if (auto p = f.point("point")) mech.fixed.push_back({*p, f.line()});
    else if (!f.has("point")) ctx.error(f.line(), "mechanics.fixed.point", "required key is missing");
  }
  for (const toml::table* lt : m.tables("load")) {
    const TableView l(ctx, *lt, "mechanics.load", {"point", "force"});
    const auto p = l.point("point");
    const auto f = l.time_table("force", 2);
    if (!l.has("point")) ctx.error(l.line(), "mechanics.load.point", "required key is missing");
    if (!l.has("force")) ctx.error(l.line(), "mechanics.load.force", "required key is missing");
    if (p && f) mech.loads.push_back({*p, *f, l.line()});
  }
  for (const toml::table* dt : m.tables("displacement")) {
    const TableView d(ctx, *dt, "mechanics.displacement", {"boundary", "point", "value", "ramp_time"});
    PrescribedDisplacement disp;
    disp.line = d.line();
    disp.boundary = d.string("boundary").value_or("");
    disp.point = d.point("point");
    if (d.has("boundary") == d.has("point"))
      ctx.error(d.line(), "mechanics.displacement", "give exactly one of 'boundary' or 'point'");
    if (auto v = d.point("value")) disp.value = *v;
    else if (!d.has("value")) ctx.error(d.line(), "mechanics.displacement.value", "required key is missing");
    disp.ramp_time = d.number("ramp_time");
    if (disp.ramp_time)
      d.require("ramp_time", std::isfinite(*disp.ramp_time) && *disp.ramp_time > 0.0,
                "must be a positive number of seconds");
    mech.displacements.push_back(std::move(disp));
  }
  for (const toml::table* tt : m.tables("traction")) {
    const TableView r(ctx, *tt, "mechanics.traction",
                      {"boundary", "normal", "normal_end", "shear", "shear_end"});
    Traction traction;
    traction.line = r.line();
    traction.boundary = r.string("boundary").value_or("");
    if (!r.has("boundary")) ctx.error(r.line(), "mechanics.traction.boundary", "required key is missing");
    traction.normal = r.time_table("normal").value_or(0.0);
    traction.shear = r.time_table("shear").value_or(0.0);
    traction.normal_end = r.time_table("normal_end").value_or(traction.normal);
    traction.shear_end = r.time_table("shear_end").value_or(traction.shear);
    if (!r.has("normal") && !r.has("shear"))
      ctx.error(r.line(), "mechanics.traction", "give 'normal' and/or 'shear'");
    mech.tractions.push_back(std::move(traction));
  }
  for (const toml::table* mt : m.tables("measure")) {
    const TableView p(ctx, *mt, "mechanics.measure", {"name", "point"});
    MeasurePoint measure;
    measure.line = p.line();
    measure.name = p.string("name").value_or("");
    if (!p.has("name")) ctx.error(p.line(), "mechanics.measure.name", "required key is missing");
    if (auto pt = p.point("point")) measure.point = *pt;
    else if (!p.has("point")) ctx.error(p.line(), "mechanics.measure.point", "required key is missing");
    for (const MeasurePoint& other : mech.measures)
      if (!measure.name.empty() && other.name == measure.name)
        ctx.error(p.line(), "mechanics.measure.name",
                  fmt::format("\"{}\" is already used (line {})", measure.name, other.line));
    mech.measures.push_back(std::move(measure));
  }
  read_rollers(ctx, m, mech);
  read_initial_stress(ctx, m, mech);
  s.mechanics = std::move(mech);
}

void read_flow(ReadContext& ctx, const TableView& root, Scenario& s) {
  const toml::table* t = root.table("flow");
  if (!t) return;
  const TableView f(ctx, *t, "flow",
                    {"fluid", "pressure", "permeability_law", "permeability_cap", "fracture_permeability_cap",
                     "boundary", "region", "transient", "probe"});
  FlowDefinition flow;
  if (const toml::table* ft = f.table("fluid")) {
    const TableView fluid(ctx, *ft, "flow.fluid", {"density", "viscosity", "compressibility"});
    flow.fluid_compressibility = fluid.number("compressibility").value_or(flow.fluid_compressibility);
    fluid.require("compressibility", flow.fluid_compressibility >= 0.0 && flow.fluid_compressibility <= kMaxStorage,
                  fmt::format("must lie in [0, {:g}] 1/Pa (water's is 4.5e-10)", kMaxStorage));
    flow.fluid_density = fluid.number_or("density", flow.fluid_density);
    flow.fluid_viscosity = fluid.number_or("viscosity", flow.fluid_viscosity);
    fluid.require("density", flow.fluid_density > 0.0, "must be > 0");
    fluid.require("viscosity", flow.fluid_viscosity > 0.0, "must be > 0");
  } else if (!f.has("fluid")) {
    ctx.defaults.push_back({"flow.fluid", "{ density = 1000, viscosity = 0.001 }"});
  }
  flow.pressure = f.choice("pressure", hydro::PressureConvention::hydrostatic);
  flow.permeability_law = f.choice("permeability_law", coupling::PermeabilityLaw::kozeny_carman);
  flow.permeability_cap = f.number_or("permeability_cap", flow.permeability_cap);
  f.require("permeability_cap", flow.permeability_cap > 0.0 && flow.permeability_cap <= kMaxPermeability,
            fmt::format("must lie in (0, {:g}] m²: beyond, pores are some 10 cm across and the flow is not Darcy's",
                        kMaxPermeability));
  // A default only the cubic law uses is listed only for it.
  flow.fracture_permeability_cap = flow.permeability_law == coupling::PermeabilityLaw::cubic
                                       ? f.number_or("fracture_permeability_cap", flow.fracture_permeability_cap)
                                       : f.number("fracture_permeability_cap").value_or(flow.fracture_permeability_cap);
  f.require("fracture_permeability_cap",
            flow.fracture_permeability_cap > 0.0 && flow.fracture_permeability_cap <= kMaxPermeability,
            fmt::format("must lie in (0, {:g}] m²: beyond, a gap is 11 cm wide and its flow is not the cubic law's",
                        kMaxPermeability));
  // A head lies within kMaxPressureHead of the model: its pressure head h − y is at most 10 GPa of water.
  const geometry::Box box = find_model_box(s);
  const double lowest_head = (box.empty() ? 0.0 : box.lo.y) - kMaxPressureHead;
  const double highest_head = (box.empty() ? 0.0 : box.hi.y) + kMaxPressureHead;

  for (const toml::table* bt : f.tables("boundary")) {
    const TableView b(ctx, *bt, "flow.boundary", {"name", "head", "pressure", "flux"});
    FlowBoundaryCondition bc;
    bc.line = b.line();
    bc.name = b.string("name").value_or("");
    if (!b.has("name")) ctx.error(b.line(), "flow.boundary.name", "required key is missing");
    // The condition's kind is the key its value is given under.
    int given = 0;
    hydro::BoundaryKind kind = bc.kind;
    for (const Spelling<hydro::BoundaryKind>& k : Spellings<hydro::BoundaryKind>::table)
      if (b.has(k.text)) ++given, kind = k.value;
    if (given != 1) {
      ctx.error(b.line(), "flow.boundary", "give exactly one of 'head', 'pressure' or 'flux'");
    } else {
      bc.kind = kind;
      bc.value = b.time_table(spell(bc.kind)).value_or(0.0);
      if (bc.kind == hydro::BoundaryKind::head)
        b.require("head", bc.value.lowest() >= lowest_head && bc.value.highest() <= highest_head,
                  fmt::format("must lie within {:g} m of the model's heights ({:g} to {:g} m): a head farther off is "
                              "a pressure past 10 GPa, beyond the strength of any rock", kMaxPressureHead,
                              lowest_head + kMaxPressureHead, highest_head - kMaxPressureHead));
      else if (bc.kind == hydro::BoundaryKind::pressure)
        b.require("pressure", std::max(-bc.value.lowest(), bc.value.highest()) <= kMaxStress,
                  fmt::format("must lie within ±{:g} Pa: 10 GPa is beyond the strength of any rock", kMaxStress));
    }
    for (const FlowBoundaryCondition& other : flow.boundaries)
      if (!bc.name.empty() && other.name == bc.name)
        ctx.error(b.line(), "flow.boundary.name",
                  fmt::format("\"{}\" already has a condition (line {})", bc.name, other.line));
    flow.boundaries.push_back(std::move(bc));
  }
  for (const toml::table* rt : f.tables("region")) {
    const TableView r(ctx, *rt, "flow.region", {"name", "polygon", "permeability"});
    FlowRegion region;
    region.line = r.line();
    region.name = r.string("name").value_or("");
    if (!r.has("name")) ctx.error(r.line(), "flow.region.name", "required key is missing");
    for (const FlowRegion& other : flow.regions)
      if (r.has("name") && other.name == region.name)
        ctx.error(r.line_of_key("name"), "flow.region.name",
                  fmt::format("a region named \"{}\" is already defined at line {}: give each its own name",
                              region.name, other.line));
    if (auto p = r.points("polygon")) {
      region.polygon = std::move(*p);
      const Polygon* domain = s.geometry ? &s.geometry->domain : nullptr;
      if (check_polygon(ctx, r.line_of_key("polygon"), "flow.region.polygon", region.polygon) && domain &&
          domain->size() >= 3 && !polygons_overlap(region.polygon, *domain))
        ctx.error(r.line_of_key("polygon"), "flow.region.polygon",
                  "the region lies wholly outside geometry.domain, so it would hold no element");
    } else if (!r.has("polygon")) {
      ctx.error(r.line(), "flow.region.polygon", "required key is missing");
    }
    if (auto k = r.number("permeability")) {
      region.permeability = *k;
      r.require("permeability", *k > 0.0 && *k <= kMaxPermeability,
                fmt::format("must lie in (0, {:g}] m²: beyond, pores are some 10 cm across and the flow is not Darcy's",
                            kMaxPermeability));
    }
    flow.regions.push_back(std::move(region));
  }
  read_transient(ctx, f, lowest_head, highest_head, flow);
  read_probes(ctx, f, flow);
  s.flow = std::move(flow);
}

void read_mesh(ReadContext& ctx, const TableView& root, Scenario& s) {
  const toml::table* t = root.table("mesh");
  const bool wanted = t || s.flow;
  if (!wanted) return;
  MeshDefinition mesh;
  // Defaults scale with the domain: 1/40 of its larger side far from fractures.
  double extent = 1.0;
  if (s.geometry && !s.geometry->domain.empty()) {
    const geometry::Box box = geometry::bounding_box(s.geometry->domain);
    extent = std::max(box.width(), box.height());
  }
  static const toml::table empty;
  const TableView m(ctx, t ? *t : empty, "mesh",
                    {"size", "fracture_size", "refine_distance", "file", "refine", "refine_tips"});
  mesh.size = m.number_or("size", extent / 40.0);
  // Derived defaults follow a valid size only, so that one bad value gives one error.
  const double base = mesh.size > 0.0 ? mesh.size : extent / 40.0;
  mesh.fracture_size = m.number_or("fracture_size", base / 10.0);
  mesh.refine_distance = m.number_or("refine_distance", 2.0 * base);
  m.require("size", mesh.size > 0.0, "must be > 0");
  m.require("fracture_size", mesh.fracture_size > 0.0, "must be > 0");
  if (mesh.size > 0.0)
    m.require("fracture_size", mesh.fracture_size <= mesh.size, "must be <= mesh.size");
  m.require("refine_distance", mesh.refine_distance > 0.0, "must be > 0");
  for (const toml::table* rt : m.tables("refine")) {
    const TableView r(ctx, *rt, "mesh.refine", {"point", "size", "radius"});
    MeshRefinePoint refine;
    const auto point = r.point("point");
    if (!r.has("point")) ctx.error(r.line(), "mesh.refine.point", "required key is missing");
    refine.size = r.required_number("size");
    refine.radius = r.number_or("radius", default_refine_radius(base, refine.size));
    r.require("size", refine.size > 0.0, "must be > 0");
    if (mesh.size > 0.0) r.require("size", refine.size <= mesh.size, "must be <= mesh.size");
    if (r.has("radius")) r.require("radius", refine.radius > 0.0, "must be > 0");
    if (point) {
      refine.point = *point;
      mesh.refine_points.push_back(refine);
    }
  }
  if (auto file = m.string("file")) {
    std::filesystem::path path(*file);
    if (path.is_relative()) path = s.file.parent_path() / path;
    check_named_file(ctx, m.line_of_key("file"), "mesh.file", path, kMaxMeshFileBytes);
    mesh.file = path;
    mesh.file_line = m.line_of_key("file");
  }
  mesh.refine_tips = m.boolean("refine_tips").value_or(false);
  if (mesh.refine_tips) {
    // The tips are the cubic law's, found on the fractures of a [geometry] domain, and refined
    // in a mesh the run generates.
    const int line = m.line_of_key("refine_tips");
    if (mesh.file)
      ctx.error(line, "mesh.refine_tips", "refines a mesh the run generates; mesh.file gives one: refine the file");
    else if (!s.flow || s.flow->permeability_law != coupling::PermeabilityLaw::cubic)
      ctx.error(line, "mesh.refine_tips",
                fmt::format("refines around the wedge tips of the cubic law; needs flow.permeability_law = \"{}\"",
                            spell(coupling::PermeabilityLaw::cubic)));
    else if (!s.geometry || s.geometry->domain.empty() || !s.mechanics)
      ctx.error(line, "mesh.refine_tips", "needs a coupled run of a [geometry] domain cut by fractures");
  }
  s.mesh = std::move(mesh);
}

// A steady coupled model whose blocks start in an in-situ stress: its first pass puts the load
// on at once, and where that moves the blocks (their in-situ stress stood with still water, not
// with the whole load) the pass is run again with the overpressure raised over 3 passes (at
// most the passes before the last), so that friction keeps the state a slow rise leaves, not
// one a sudden load throws the blocks into. A model that starts unstressed takes its whole load
// at once, gravity and water together (docs/coupling.md, "Relaxation, acceleration and the load
// ramp"; the measurement: docs/studies/2026-11-30-in-situ-ramp.md). 0: no such ramp.
int default_ramp_if_moved(const Scenario& s) {
  constexpr int kInSituRampPasses = 3;
  const bool steady_coupled = s.flow && !s.flow->transient && s.mechanics;
  if (!steady_coupled || !s.mechanics->initial_stress) return 0;
  const int passes = std::min(kInSituRampPasses, s.coupling.max_iterations - 1);
  return passes > 1 ? passes : 0;
}

std::string ramp_default_text(int ramp_if_moved) {
  return ramp_if_moved > 1 ? fmt::format("1, or {} if the load at once moves the blocks from their in-situ stress",
                                         ramp_if_moved)
                           : "1";
}

void read_coupling(ReadContext& ctx, const TableView& root, Scenario& s) {
  // Passes settle by default where they can: at rest means nothing in a dynamic analysis,
  // whose blocks keep their velocity.
  const bool static_analysis = s.mechanics && s.mechanics->analysis == dda::Analysis::static_;
  s.coupling.settle = static_analysis;
  const toml::table* t = root.table("coupling");
  if (!t) {
    s.coupling.ramp_if_moved = default_ramp_if_moved(s);
    if (s.flow && s.mechanics)
      ctx.defaults.push_back({"coupling", fmt::format("{{ tolerance = 1e-4, max_iterations = 50, relaxation = 1, "
                                                      "ramp_passes = {}, settle = {} }}",
                                                      ramp_default_text(s.coupling.ramp_if_moved), static_analysis)});
    return;
  }
  const TableView c(ctx, *t, "coupling",
                    {"tolerance", "max_iterations", "relaxation", "acceleration", "ramp_passes", "ramp", "settle",
                     "pseudo_time_step"});
  s.coupling.tolerance = c.number_or("tolerance", s.coupling.tolerance);
  c.require("tolerance", s.coupling.tolerance > 0.0, "must be > 0");
  if (auto n = c.integer("max_iterations", 1, 1'000'000)) {
    s.coupling.max_iterations = *n;
  } else if (!c.has("max_iterations")) {
    ctx.defaults.push_back({"coupling.max_iterations", "50"});
  }
  s.coupling.relaxation = c.number_or("relaxation", s.coupling.relaxation);
  c.require("relaxation", s.coupling.relaxation > 0.0 && s.coupling.relaxation <= 1.0,
            "must lie in (0, 1]");
  s.coupling.acceleration = c.choice("acceleration", coupling::Acceleration::none);
  if (auto n = c.integer("ramp_passes", 1, 1'000'000)) {
    s.coupling.ramp_passes = *n;
    // A pass counts towards convergence only once it and the pass before it had the full load:
    // a ramp as long as the passes allowed ends every steady run unconverged.
    c.require("ramp_passes", (s.flow && s.flow->transient) || *n < s.coupling.max_iterations,
              fmt::format("must be below coupling.max_iterations ({}): the first pass that can count towards "
                          "convergence is pass ramp_passes + 1",
                          s.coupling.max_iterations));
  } else if (!c.has("ramp_passes")) {
    s.coupling.ramp_if_moved = default_ramp_if_moved(s);
    if (s.flow && s.mechanics) ctx.defaults.push_back({"coupling.ramp_passes", ramp_default_text(s.coupling.ramp_if_moved)});
  }
  // Read (and its default listed) only where a ramp is asked for or the key is given.
  if (c.has("ramp") || s.coupling.ramp_passes > 1 || s.coupling.ramp_if_moved > 1)
    s.coupling.ramp = c.choice("ramp", coupling::RampedLoad::overpressure);
  if (c.has("pseudo_time_step")) {
    s.coupling.pseudo_time_step = c.number_or("pseudo_time_step", 0.0);
    c.require("pseudo_time_step", s.coupling.pseudo_time_step > 0.0, "must be > 0 (s); leave it out for none");
  }
  if (auto settle = c.boolean("settle")) {
    s.coupling.settle = *settle;
  } else if (s.flow && s.mechanics) {
    ctx.defaults.push_back({"coupling.settle", static_analysis ? "true" : "false"});
  }
  c.require("settle", !s.coupling.settle || !s.mechanics || static_analysis,
            fmt::format("needs mechanics.analysis = \"{}\"", spell(dda::Analysis::static_)));
}

// output.fields: which of the series "fluid", "blocks", "contacts" and "fractures" to write, each once.
void read_output_fields(ReadContext& ctx, const toml::node& fields, OutputFields& chosen) {
  const toml::array* a = fields.as_array();
  if (!a) {
    ctx.error(line_of(fields), "output.fields", "expected an array such as [\"fluid\", \"blocks\", \"contacts\"]");
    return;
  }
  chosen = {false, false, false, false};
  for (const toml::node& item : *a) {
    const auto name = item.value<std::string>();
    bool* series = !name                ? nullptr
                   : *name == "fluid"    ? &chosen.fluid
                   : *name == "blocks"   ? &chosen.blocks
                   : *name == "contacts" ? &chosen.contacts
                   : *name == "fractures" ? &chosen.fractures
                                         : nullptr;
    if (!series) {
      ctx.error(line_of(item), "output.fields",
                "each series must be \"fluid\", \"blocks\", \"contacts\" or \"fractures\"");
    } else if (*series) {
      ctx.error(line_of(item), "output.fields", fmt::format("\"{}\" is listed twice", *name));
    } else {
      *series = true;
    }
  }
}

void read_output(ReadContext& ctx, const TableView& root, Scenario& s) {
  const toml::table* t = root.table("output");
  static const toml::table empty;
  const TableView o(ctx, t ? *t : empty, "output", {"directory", "every", "fields", "figures"});
  if (auto dir = o.string("directory")) {
    s.output.directory = *dir;
    o.require("directory", !dir->empty(), "must not be empty");
  } else {
    s.output.directory = std::filesystem::path("out") / s.file.stem();
    ctx.defaults.push_back({"output.directory", fmt::format("\"{}\"", s.output.directory.string())});
  }
  if (auto every = o.integer("every", 1, kMaxSteps)) {
    s.output.every = *every;
  } else {
    ctx.defaults.push_back({"output.every", std::to_string(s.output.every)});
  }
  if (const toml::node* fields = o.node("fields")) read_output_fields(ctx, *fields, s.output.fields);
  if (const toml::node* figures = o.node("figures")) {
    s.output.figures.clear();
    const toml::array* a = figures->as_array();
    if (!a) {
      ctx.error(line_of(*figures), "output.figures", "expected an array such as [\"png\", \"svg\"]");
    } else {
      for (const toml::node& item : *a) {
        const auto format = item.value<std::string>();
        if (!format || (*format != "png" && *format != "svg" && *format != "pdf"))
          ctx.error(line_of(item), "output.figures", "each format must be \"png\", \"svg\" or \"pdf\"");
        else s.output.figures.push_back(*format);
      }
    }
  }
}

}  // namespace

Scenario parse_scenario(std::string_view text, const std::filesystem::path& file) {
  ReadContext ctx;
  ctx.file = file.string();
  toml::table document;
  try {
    document = toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    ctx.error(static_cast<int>(e.source().begin.line), "",
              "malformed TOML: " + std::string(e.description()));
    throw ScenarioError(std::move(ctx.errors));
  }

  Scenario s;
  s.file = file;
  const TableView root(ctx, document, "",
                       {"title", "geometry", "boundaries", "material", "joint", "mechanics",
                        "flow", "mesh", "coupling", "output"});
  s.title = root.string("title").value_or(file.stem().string());
  read_geometry(ctx, root, s);
  read_boundaries(ctx, root, s);
  read_materials(ctx, root, s);
  read_joint(ctx, root, s);
  read_mechanics(ctx, root, s);
  read_flow(ctx, root, s);
  read_mesh(ctx, root, s);
  read_coupling(ctx, root, s);
  read_output(ctx, root, s);
  validate_scenario(ctx, root, s);

  if (!ctx.errors.empty()) {
    std::stable_sort(ctx.errors.begin(), ctx.errors.end(),
                     [](const Diagnostic& a, const Diagnostic& b) { return a.line < b.line; });
    throw ScenarioError(std::move(ctx.errors));
  }
  s.defaults_used = std::move(ctx.defaults);
  return s;
}

Scenario read_scenario(const std::filesystem::path& file) {
  const auto refuse = [&](const std::string& why) { return ScenarioError({{file.string(), 0, "", why}}); };
  switch (inspect_input_file(file, kMaxScenarioBytes)) {
    case InputFileProblem::none: break;
    case InputFileProblem::missing: throw refuse("cannot open the scenario file: no such file");
    case InputFileProblem::folder: throw refuse("is a folder, not a scenario file");
    case InputFileProblem::not_regular: throw refuse("is not a regular file; give a scenario file (TOML)");
    case InputFileProblem::too_large:
      throw refuse(fmt::format("is larger than {} MiB; a scenario file is a few kilobytes (large inputs go in "
                               "mesh.file)", kMaxScenarioBytes >> 20));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw refuse("cannot open the scenario file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scenario(text.str(), file);
}

}  // namespace hydrodda::scenario
