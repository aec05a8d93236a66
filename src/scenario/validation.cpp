#include "scenario/validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "scenario/material_regions.hpp"
#include "scenario/rollers_and_initial_stress.hpp"
#include "scenario/transient_reading.hpp"
#include "scenario/tessellations.hpp"

namespace hydrodda::scenario {

bool check_polygon(ReadContext& ctx, int line, const std::string& key, const Polygon& polygon) {
  if (polygon.size() > kMaxPolygonVertices) {
    ctx.error(line, key, fmt::format("a polygon of {} vertices; at most {} (meshing time grows without bound "
                                     "beyond: simplify the outline)", polygon.size(), kMaxPolygonVertices));
    return false;
  }
  if (polygon.size() < 3) {
    ctx.error(line, key, fmt::format("a polygon needs at least 3 vertices, got {}", polygon.size()));
    return false;
  }
  const geometry::Box box = geometry::bounding_box(polygon);
  const double scale = std::max(box.width(), box.height());
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    if (polygon[i] == polygon[(i + 1) % polygon.size()]) {
      ctx.error(line, key, fmt::format("vertex {} repeats the vertex before it", (i + 1) % polygon.size() + 1));
      return false;
    }
  }
  // Degenerate: every vertex on one line through the first vertex and the one farthest from it
  // (measured on coordinates over the polygon's size, which cannot overflow: at 1e308 m the
  // squares did, and every polygon looked flat).
  const auto scaled = [&](Point p) { return (p - polygon[0]) * (1.0 / scale); };
  std::size_t far = 0;
  for (std::size_t i = 1; i < polygon.size(); ++i)
    if (geometry::norm(scaled(polygon[i])) > geometry::norm(scaled(polygon[far]))) far = i;
  double spread = 0.0;
  for (Point p : polygon) spread = std::max(spread, std::abs(geometry::orient({0.0, 0.0}, scaled(polygon[far]), scaled(p))));
  if (!(spread > 1e-12)) {
    ctx.error(line, key, "degenerate polygon: its vertices lie on one line, so its area is zero");
    return false;
  }
  if (auto crossing = geometry::find_self_intersection(polygon)) {
    ctx.error(line, key,
              fmt::format("self-intersecting polygon: edge {} (vertices {}-{}) meets edge {} "
                          "(vertices {}-{})",
                          crossing->first + 1, crossing->first + 1,
                          crossing->first + 1 == static_cast<int>(polygon.size()) ? 1 : crossing->first + 2,
                          crossing->second + 1, crossing->second + 1,
                          crossing->second + 1 == static_cast<int>(polygon.size()) ? 1 : crossing->second + 2));
    return false;
  }
  if (geometry::signed_area(polygon) < 0.0) {
    ctx.error(line, key, "vertices run clockwise: list them counter-clockwise");
    return false;
  }
  return true;
}

geometry::Box find_model_box(const Scenario& s) {
  geometry::Box box;
  if (!s.geometry) return box;
  for (Point p : s.geometry->domain) box.add(p);
  for (const BlockDefinition& b : s.geometry->blocks)
    for (Point p : b.vertices) box.add(p);
  return box;
}

bool segment_meets_polygon(Point a, Point b, const Polygon& polygon) {
  if (polygon.size() < 3) return true;  // no domain to test against: reported elsewhere
  if (geometry::contains(polygon, a) || geometry::contains(polygon, b)) return true;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (geometry::segments_intersect(a, b, polygon[i], polygon[(i + 1) % polygon.size()])) return true;
  return false;
}

namespace {

std::vector<std::string> boundary_names(const Scenario& s) {
  std::vector<std::string> names;
  for (const BoundarySegment& b : s.boundaries) names.push_back(b.name);
  return names;
}

void check_boundary_reference(ReadContext& ctx, const Scenario& s, int line, const std::string& key,
                              const std::string& name) {
  if (name.empty() || s.find_boundary(name)) return;
  const auto names = boundary_names(s);
  std::string message = fmt::format("no boundary named \"{}\"", name);
  const std::string nearest = suggest_nearest(name, names);
  if (!nearest.empty()) message += fmt::format(" (did you mean \"{}\"?)", nearest);
  else message += fmt::format("; boundaries are: {}", fmt::join(names, ", "));
  ctx.error(line, key, message);
}

// The length of `segment` that runs along the polygon's edges (collinear within a relative 1e-9
// of the polygon's size, as the mesh's boundary edges are named): the flow can only take a
// condition where this is more than nothing.
// Measured on coordinates over the outline's size (no overflow at 1e308 m); in those units.
double length_along_outline(const Segment& given, const Polygon& outline) {
  const geometry::Box box = geometry::bounding_box(outline);
  const double scale = std::max(box.width(), box.height());
  const auto scaled = [&](Point p) { return (p - box.lo) * (1.0 / scale); };
  const Segment segment{scaled(given.from), scaled(given.to)};
  const double tolerance = 1e-9;
  double length = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Point a = scaled(outline[i]), b = scaled(outline[(i + 1) % outline.size()]);
    const double edge = geometry::distance(a, b);
    const auto off_line = [&](Point p) { return std::abs(geometry::orient(a, b, p)) / edge > tolerance; };
    if (off_line(segment.from) || off_line(segment.to)) continue;
    const Point along = (b - a) * (1.0 / edge);
    const double s0 = geometry::dot(segment.from - a, along), s1 = geometry::dot(segment.to - a, along);
    length += std::max(0.0, std::min(edge, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1)));
  }
  return length;
}

// A [[flow.boundary]] on a [boundaries] segment that does not run along the domain's outline
// (drawn inside or outside it, or a default such as `bottom` redefined off it) has no mesh
// edges to take the condition: refused here, not after meshing.
void check_flow_boundary_on_domain(ReadContext& ctx, const Scenario& s, const FlowBoundaryCondition& bc) {
  const BoundarySegment* boundary = s.find_boundary(bc.name);
  if (!boundary || !s.geometry || s.geometry->domain.size() < 3) return;
  if (boundary->segment.from == boundary->segment.to) return;  // refused for its length already
  if (length_along_outline(boundary->segment, s.geometry->domain) > 1e-9) return;
  const Segment& g = boundary->segment;
  ctx.error(bc.line, "flow.boundary.name",
            fmt::format("boundary \"{}\" (from ({:g}, {:g}) to ({:g}, {:g})) does not run along the edge of "
                        "geometry.domain, so no mesh edge can take its condition",
                        bc.name, g.from.x, g.from.y, g.to.x, g.to.y));
}

}  // namespace

// Two polygons overlap when an edge of one properly crosses an edge of the other, or a vertex,
// a piece of an edge or the centroid of one lies strictly inside the other.
bool polygons_overlap(const Polygon& a, const Polygon& b) {
  // Coordinates in a file carry a dozen digits, so touching blocks may overlap by round-off:
  // depths under a relative 1e-9 of the blocks' size count as touching.
  geometry::Box box = geometry::bounding_box(a);
  const geometry::Box box_b = geometry::bounding_box(b);
  box.add(box_b.lo);
  box.add(box_b.hi);
  const double scale = std::max(box.width(), box.height());
  const double tolerance = 1e-9 * scale;
  const auto side = [&](Point p, Point q, Point r) {  // sign of orient, 0 within tolerance
    const double o = geometry::orient(p, q, r) / std::max(geometry::distance(p, q), 1e-300);
    return o > tolerance ? 1 : (o < -tolerance ? -1 : 0);
  };
  const auto strictly_inside = [&](const Polygon& poly, Point p) {
    if (!geometry::contains(poly, p)) return false;
    for (std::size_t i = 0; i < poly.size(); ++i)
      if (geometry::distance_to_segment(p, poly[i], poly[(i + 1) % poly.size()]) <= tolerance) return false;
    return true;
  };
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Point p = a[i], q = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Point r = b[j], t = b[(j + 1) % b.size()];
      if (side(r, t, p) * side(r, t, q) < 0 && side(p, q, r) * side(p, q, t) < 0) return true;
    }
  }
  for (Point p : a)
    if (strictly_inside(b, p)) return true;
  for (Point p : b)
    if (strictly_inside(a, p)) return true;
  // With no proper crossing, an edge enters the other block only between the other's vertices
  // that lie on it: cut each edge there and test the pieces' midpoints (two squares offset by
  // half a side have every vertex and both centroids on the other's boundary).
  const auto piece_inside = [&](const Polygon& cut, const Polygon& other) {
    for (std::size_t i = 0; i < cut.size(); ++i) {
      const Point p = cut[i], q = cut[(i + 1) % cut.size()];
      const double length = geometry::distance(p, q);
      std::vector<double> at{0.0, 1.0};
      for (Point r : other)
        if (geometry::distance_to_segment(r, p, q) <= tolerance)
          at.push_back(std::clamp(geometry::dot(r - p, q - p) / (length * length), 0.0, 1.0));
      std::sort(at.begin(), at.end());
      for (std::size_t k = 0; k + 1 < at.size(); ++k)
        if ((at[k + 1] - at[k]) * length > tolerance && strictly_inside(other, p + (0.5 * (at[k] + at[k + 1])) * (q - p)))
          return true;
    }
    return false;
  };
  if (piece_inside(a, b) || piece_inside(b, a)) return true;
  return strictly_inside(b, geometry::centroid(a)) || strictly_inside(a, geometry::centroid(b));
}

namespace {

// The model's size and place (12, 15 of the robustness list): Gmsh merges points closer than
// its tolerance of 1e-8 m, so a model under a millimetre fails inside it; and a position of
// magnitude |x| resolves displacements only to 2.2e-16 |x|, so coordinates far from the origin
// (1e9 m for a metre-sized model) lose the answer. Within 1e6 sizes of the origin that
// resolution stays 2,000 times below the penetration tolerance (5e-7 of the model's height).
void check_model_extent(ReadContext& ctx, const TableView& root, const Scenario& s) {
  const geometry::Box box = find_model_box(s);
  if (box.empty()) return;
  const double size = std::max(box.width(), box.height());
  const int line = root.line_of_key("geometry");
  if (!(size >= kMinModelSize && size <= kMaxModelSize)) {
    ctx.error(line, "geometry",
              fmt::format("the model spans {:g} m; the supported size is {:g} m to {:g} m (Gmsh merges points "
                          "closer than 1e-8 m): give lengths in metres",
                          size, kMinModelSize, kMaxModelSize));
    return;
  }
  const double reach = std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.hi.x), std::abs(box.hi.y)});
  if (reach > kMaxOriginDistance * size)
    ctx.error(line, "geometry",
              fmt::format("coordinates reach {:g} m from the origin, {:.3g} times the model's size of {:g} m; at most "
                          "{:g} times, or positions lose the digits displacements need: move the origin into the "
                          "model (subtract ({:.12g}, {:.12g}))",
                          reach, reach / size, size, kMaxOriginDistance, 0.5 * (box.lo.x + box.hi.x),
                          0.5 * (box.lo.y + box.hi.y)));
}

void check_block_overlaps(ReadContext& ctx, const std::vector<BlockDefinition>& blocks) {
  // Sweep along x over bounding boxes so that only neighbours are compared.
  std::vector<geometry::Box> boxes;
  for (const BlockDefinition& b : blocks) boxes.push_back(geometry::bounding_box(b.vertices));
  std::vector<std::size_t> order(blocks.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return boxes[i].lo.x < boxes[j].lo.x || (boxes[i].lo.x == boxes[j].lo.x && i < j);
  });
  for (std::size_t oi = 0; oi < order.size(); ++oi) {
    const std::size_t i = order[oi];
    if (blocks[i].vertices.size() < 3) continue;
    for (std::size_t oj = oi + 1; oj < order.size(); ++oj) {
      const std::size_t j = order[oj];
      if (boxes[j].lo.x > boxes[i].hi.x) break;
      if (blocks[j].vertices.size() < 3 || !boxes[i].overlaps(boxes[j])) continue;
      if (polygons_overlap(blocks[i].vertices, blocks[j].vertices)) {
        const auto [first, second] = std::minmax(blocks[i].line, blocks[j].line);
        ctx.error(second, "geometry.block",
                  fmt::format("this block overlaps the block defined at line {}", first));
      }
    }
  }
}

void resolve_materials(ReadContext& ctx, const TableView& root, Scenario& s) {
  if (!s.geometry) return;
  std::vector<std::string> names;
  for (const MaterialDefinition& m : s.materials) names.push_back(m.name);
  for (BlockDefinition& b : s.geometry->blocks) {
    if (b.material.empty()) {
      if (s.materials.size() == 1) b.material = s.materials[0].name;
      else if (s.materials.size() > 1)
        ctx.error(b.line, "geometry.block.material",
                  fmt::format("several materials are defined ({}): name one", fmt::join(names, ", ")));
    } else if (!s.find_material(b.material)) {
      std::string message = fmt::format("no material named \"{}\"", b.material);
      const std::string nearest = suggest_nearest(b.material, names);
      if (!nearest.empty()) message += fmt::format(" (did you mean \"{}\"?)", nearest);
      ctx.error(b.line, "geometry.block.material", message);
    }
  }
  // Flow alone can do without a material when regions fix the permeability; whether they
  // cover the whole domain is checked on the mesh.
  bool permeability_fixed = false;
  if (s.flow)
    for (const FlowRegion& r : s.flow->regions) permeability_fixed = permeability_fixed || r.permeability;
  const bool needs_material = s.mechanics || (s.flow && !permeability_fixed);
  if (needs_material && s.materials.empty())
    ctx.error(root.line(), "material", "no material is defined: add a [material.NAME] table");
  check_material_regions(ctx, root, s);
}

void check_material_fields(ReadContext& ctx, const TableView& root, const Scenario& s) {
  for (const MaterialDefinition& m : s.materials) {
    const int line = root.line_of_key("material");
    const auto require = [&](const std::optional<double>& value, const std::string& key) {
      const std::string path = "material." + m.name + "." + key;
      if (!value && !ctx.has_error(path)) ctx.error(line, path, "required by [mechanics]");
    };
    if (s.mechanics) {
      require(m.density, "density");
      require(m.young, "young");
      require(m.poisson, "poisson");
    }
    if (s.flow && coupling::describe(s.flow->permeability_law).needs_grain_diameter && !m.grain_diameter &&
        !m.permeability)
      ctx.error(line, "material." + m.name + ".grain_diameter",
                fmt::format("required by flow.permeability_law = \"{}\"", spell(s.flow->permeability_law)));
  }
}

// Static analysis seeks equilibrium: with no support at all (no fixed block, no fixed point, no
// prescribed displacement) the stiffness has the rigid-body motions of the whole assembly in its
// null space, so any load moves it without end. Dynamic analysis has inertia and is fine.
void check_static_support(ReadContext& ctx, const TableView& root, const Scenario& s) {
  if (!s.mechanics || s.mechanics->analysis != dda::Analysis::static_ || !s.geometry) return;
  const bool fixed_block = std::any_of(s.geometry->blocks.begin(), s.geometry->blocks.end(),
                                       [](const BlockDefinition& b) { return b.fixed; });
  if (fixed_block || !s.mechanics->fixed.empty() || !s.mechanics->displacements.empty() || !s.mechanics->rollers.empty())
    return;
  ctx.error(root.line_of_key("mechanics"), "mechanics.analysis",
            fmt::format("static analysis with nothing to hold the blocks: no fixed block (geometry.block fixed = "
                        "true), no [[mechanics.fixed]] point, no [[mechanics.displacement]] and no "
                        "[[mechanics.roller]], so nothing stops rigid-body motion; add a support or use analysis = "
                        "\"{}\"",
                        spell(dda::Analysis::dynamic)));
}

}  // namespace

void validate_scenario(ReadContext& ctx, const TableView& root, Scenario& s) {
  if (!s.mechanics && !s.flow)
    ctx.error(root.line(), "", "nothing to run: give a [mechanics] and/or a [flow] section");
  if ((s.mechanics || s.flow) && !s.geometry && !(s.mesh && s.mesh->file))
    ctx.error(root.line(), "geometry", "a [geometry] section is required");
  if (s.mechanics && !s.geometry)
    ctx.error(root.line_of_key("mechanics"), "geometry", "[mechanics] needs a [geometry] section");
  if (s.flow && s.geometry && s.geometry->domain.empty() && !(s.mesh && s.mesh->file))
    ctx.error(root.line_of_key("flow"), "geometry.domain",
              "[flow] needs the fluid domain: give geometry.domain or mesh.file");

  resolve_materials(ctx, root, s);
  check_material_fields(ctx, root, s);
  if (s.geometry) {
    check_model_extent(ctx, root, s);
    check_block_overlaps(ctx, s.geometry->blocks);
  }

  check_static_support(ctx, root, s);
  check_initial_stress_gradient(ctx, s);
  check_initial_stress_across_model(ctx, s);
  check_joint_types(ctx, s);
  check_transient(ctx, root, s);
  check_tessellations(ctx, s);
  if (s.mechanics) {
    for (const PrescribedDisplacement& d : s.mechanics->displacements)
      check_boundary_reference(ctx, s, d.line, "mechanics.displacement.boundary", d.boundary);
    for (const Traction& t : s.mechanics->tractions)
      check_boundary_reference(ctx, s, t.line, "mechanics.traction.boundary", t.boundary);
    for (const RollerDefinition& r : s.mechanics->rollers)
      check_boundary_reference(ctx, s, r.line, "mechanics.roller.boundary", r.boundary);
  }
  if (s.flow) {
    bool head_fixed = false;
    // With a user's mesh file the flow boundaries are its physical curves, known only once the
    // mesh is read: the flow solver checks those names then.
    const bool names_from_mesh_file = s.mesh && s.mesh->file;
    for (const FlowBoundaryCondition& bc : s.flow->boundaries) {
      if (!names_from_mesh_file) {
        check_boundary_reference(ctx, s, bc.line, "flow.boundary.name", bc.name);
        check_flow_boundary_on_domain(ctx, s, bc);
      }
      head_fixed = head_fixed || bc.kind != hydro::BoundaryKind::flux;
    }
    if (!head_fixed)
      ctx.error(root.line_of_key("flow"), "flow.boundary",
                "nothing fixes the head: give at least one boundary a 'head' or a 'pressure'");
  }
}

namespace {

std::string joint_type_names(const Scenario& s) {
  if (s.joint_types.empty()) return "there are none: define one as [joint.NAME]";
  std::string names;
  for (const JointDefinition& j : s.joint_types) names += (names.empty() ? "" : ", ") + j.name;
  return "the types are " + names;
}

// A trace's `joint = "NAME"` names a [joint.NAME].
void check_joint_reference(ReadContext& ctx, const Scenario& s, const std::string& file, int line,
                           const std::string& key, const std::string& name) {
  if (s.joint_type_index(name) >= 0) return;
  ctx.errors.push_back({file, line, key, fmt::format("joint type \"{}\" is not defined ({})", name, joint_type_names(s))});
}

}  // namespace

void check_joint_types(ReadContext& ctx, const Scenario& s) {
  if (s.geometry) {
    const GeometryDefinition& g = *s.geometry;
    for (const TraceJoint& j : g.fracture_joints)
      check_joint_reference(ctx, s, ctx.file, j.line, "geometry.fracture.joint", j.name);
    for (const JointSetDefinition& set : g.joint_sets)
      check_joint_reference(ctx, s, ctx.file, set.joint.line, "geometry.joint_set.joint", set.joint.name);
    if (g.fractures_file)
      for (const FileFracture& f : g.file_fractures)
        check_joint_reference(ctx, s, g.fractures_file->string(), f.line, "geometry.fractures_file", f.joint);
  }
  const bool cut_domain = s.geometry && !s.geometry->domain.empty();
  for (int t = 0; t < s.joint_type_count(); ++t) {
    const JointDefinition& j = s.joint_type(t);
    const std::string table = j.name.empty() ? "joint" : "joint." + j.name;
    // A named type's keys inherited from [joint] are reported once, there.
    const bool own_hydraulic = t == 0 || j.hydraulic_line != s.joint.hydraulic_line;
    const bool own_barrier = t == 0 || j.barrier_line != s.joint.barrier_line;
    // Joint hydraulic apertures and barriers belong to the traces a domain is cut along; the
    // apertures are measured on the blocks' contacts. Each type conducts by its own law.
    if (j.hydraulic() && own_hydraulic && !cut_domain)
      ctx.error(j.hydraulic_line, table + ".residual_aperture",
                "joint hydraulic apertures need a geometry.domain cut by fractures (joints are its traces)");
    if (j.hydraulic() && own_hydraulic && s.flow && !s.mechanics)
      ctx.error(j.hydraulic_line, table + ".residual_aperture",
                "joint hydraulic apertures are measured on the blocks' contacts: they need a [mechanics] section "
                "(a flow-only run keeps the porosity law)");
    if (j.barrier() && own_barrier && s.mesh && s.mesh->file)
      ctx.error(j.barrier_line, table + ".barrier_permeability",
                "a joint's barrier is meshed as a strip the elements follow: it needs the mesh made from the scenario, "
                "not mesh.file");
    if (j.barrier() && own_barrier && !cut_domain)
      ctx.error(j.barrier_line, table + ".barrier_permeability",
                "a joint's barrier lies along the traces a geometry.domain is cut by: give the domain and its fractures");
  }
}

}  // namespace hydrodda::scenario
