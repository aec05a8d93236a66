#include "scenario/tessellations.hpp"

#include <fmt/format.h>

#include <limits>

#include "scenario/spellings.hpp"
#include "scenario/validation.hpp"

namespace hydrodda::scenario {

double estimate_sub_blocks(const TessellationDefinition& t, const Polygon& domain) {
  const Polygon& region = t.region.empty() ? domain : t.region;
  if (region.size() < 3 || !(t.size > 0.0)) return 0.0;
  // Some six triangles a cell, of either kind (a Voronoi cell is zoned into its triangles).
  return 6.0 * geometry::area(region) / (t.size * t.size);
}

namespace {
// geometry.tessellate.cracks (and .paths): straight segments inside the region, each at least
// two sub-blocks long (a pair of seeds on either side of it every `size`).
void read_segments(ReadContext& ctx, const TableView& t, TessellationDefinition& tess, const std::string& name,
                   std::vector<Segment>& out, int& line_of_key) {
  if (!t.has(name)) return;
  line_of_key = t.line_of_key(name);
  const std::string key = t.key_path(name);
  const std::string what = name == "cracks" ? "a crack" : "a path";
  for (auto& [points, line] : t.point_lists(name)) {
    if (points.size() != 2) {
      ctx.error(line, key, what + " is a straight segment: two points [[x1, y1], [x2, y2]]");
      continue;
    }
    const double length = geometry::distance(points[0], points[1]);
    if (tess.size > 0.0 && !(length >= 2.0 * tess.size)) {
      ctx.error(line, key,
                fmt::format("{} {} m long is shorter than two sub-blocks (2 size = {} m): make it longer or size "
                            "smaller",
                            what, format_number(length), format_number(2.0 * tess.size)));
      continue;
    }
    if (!tess.region.empty() && !(geometry::contains(tess.region, points[0]) && geometry::contains(tess.region, points[1]))) {
      ctx.error(line, key, what + " must lie inside the tessellation's region");
      continue;
    }
    out.push_back({points[0], points[1]});
  }
}
}  // namespace

void read_tessellations(ReadContext& ctx, const TableView& g, GeometryDefinition& geometry) {
  int index = 0;
  double total = 0.0;
  int last_line = 0;
  for (const toml::table* table : g.tables("tessellate")) {
    const TableView t(ctx, *table, "geometry.tessellate", {"kind", "size", "region", "seed", "joint", "cracks", "paths"});
    TessellationDefinition tess;
    tess.line = last_line = t.line();
    const std::string indexed = fmt::format("geometry.tessellate[{}]", index++);
    tess.kind = t.choice("kind", geometry::TessellationKind::voronoi);
    if (!t.has("size")) ctx.error(t.line(), t.key_path("size"), "required key is missing");
    tess.size = t.number("size").value_or(0.0);
    if (t.has("size")) t.require("size", tess.size > 0.0, "must be > 0 (m)");
    if (auto joint = t.string("joint")) tess.joint = {*joint, t.line_of_key("joint")};
    if (auto seed = t.integer("seed", 0, std::numeric_limits<int>::max())) {
      tess.seed = static_cast<std::uint64_t>(*seed);
    } else if (!t.has("seed")) {
      ctx.defaults.push_back({indexed + ".seed", "0"});
    }
    if (auto region = t.points("region")) {
      tess.region = std::move(*region);
      if (check_polygon(ctx, t.line_of_key("region"), t.key_path("region"), tess.region) &&
          geometry.domain.size() >= 3 && !polygons_overlap(tess.region, geometry.domain))
        ctx.error(t.line_of_key("region"), t.key_path("region"), "the region lies wholly outside geometry.domain");
    }
    read_segments(ctx, t, tess, "cracks", tess.cracks, tess.cracks_line);
    read_segments(ctx, t, tess, "paths", tess.paths, tess.paths_line);
    // A size larger than the region would make one sub-block of it, or none.
    const Polygon& region = tess.region.empty() ? geometry.domain : tess.region;
    if (tess.size > 0.0 && region.size() >= 3 && tess.size > geometry::width_across_edges(region))
      ctx.error(t.line_of_key("size"), t.key_path("size"),
                fmt::format("{} m is larger than the region it tessellates ({} m across at its narrowest)",
                            format_number(tess.size), format_number(geometry::width_across_edges(region))));
    total += estimate_sub_blocks(tess, geometry.domain);
    geometry.tessellations.push_back(std::move(tess));
  }
  if (total > kMaxSubBlocks)
    ctx.error(last_line, "geometry.tessellate.size",
              fmt::format("the tessellations would make some {:.3g} sub-blocks (six for each region's area over "
                          "size²: a Voronoi cell is zoned into triangles as the triangles' kind cuts it); at most "
                          "{:g} fit this machine's memory: make size larger or the region smaller",
                          total, kMaxSubBlocks));
}

void check_tessellations(ReadContext& ctx, const Scenario& s) {
  if (!s.geometry || s.geometry->tessellations.empty()) return;
  for (const TessellationDefinition& t : s.geometry->tessellations) {
    if (s.geometry->domain.empty()) {
      ctx.error(t.line, "geometry.tessellate", "tessellates the blocks cut from a geometry.domain: give one");
      continue;
    }
    const int type = s.joint_type_index(t.joint.name);
    if (type < 0) {
      std::string names;
      for (const JointDefinition& j : s.joint_types) names += (names.empty() ? "" : ", ") + j.name;
      ctx.error(t.joint.line, "geometry.tessellate.joint",
                fmt::format("joint type \"{}\" is not defined ({})", t.joint.name,
                            names.empty() ? "there are none: define one as [joint.NAME]" : "the types are " + names));
      continue;
    }
    const JointDefinition& j = s.joint_type(type);
    // A softening bond's critical opening w_c = 2 G_f / T: no strength, no softening law.
    if (j.fracture_energy && *j.fracture_energy > 0.0 && !(j.tensile_strength > 0.0))
      ctx.error(j.fracture_energy_line, (j.name.empty() ? "joint" : "joint." + j.name) + ".fracture_energy",
                "a softening bond (geometry.tessellate, line " + std::to_string(t.line) +
                    ") softens from its tensile_strength over its fracture energy: give the type a tensile_strength "
                    "> 0, or leave fracture_energy out");
  }
}

}  // namespace hydrodda::scenario
