#include "run/sub_blocks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/tessellation.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::run {

namespace {

using geometry::Point;
using geometry::Polygon;

// One tessellation's seeds: a jittered grid over its region's box, row by row
// (geometry::generate_seeds), and the part of it near a block found by rows and columns.
struct SeedField {
  geometry::Box box;
  double size = 0.0;
  long long columns = 0;
  long long rows = 0;
  std::vector<Point> seeds;

  std::vector<Point> near(const geometry::Box& block) const {
    const auto index = [&](double v, double lo, long long count) {
      return std::clamp(static_cast<long long>(std::floor((v - lo) / size)), 0LL, std::max(count - 1, 0LL));
    };
    std::vector<Point> out;
    for (long long j = index(block.lo.y, box.lo.y, rows); j <= index(block.hi.y, box.lo.y, rows); ++j)
      for (long long i = index(block.lo.x, box.lo.x, columns); i <= index(block.hi.x, box.lo.x, columns); ++i)
        out.push_back(seeds[static_cast<std::size_t>(j * columns + i)]);
    return out;
  }
};

SeedField make_seed_field(const scenario::TessellationDefinition& t, const Polygon& domain) {
  SeedField field;
  field.box = geometry::bounding_box(t.region.empty() ? domain : t.region);
  field.size = t.size;
  field.columns = static_cast<long long>(std::ceil(field.box.width() / t.size));
  field.rows = static_cast<long long>(std::ceil(field.box.height() / t.size));
  field.seeds = geometry::generate_seeds(field.box, t.size, t.seed);
  return field;
}

}  // namespace

void tessellate_blocks(const scenario::Scenario& s, ModelGeometry& model) {
  const scenario::GeometryDefinition& g = *s.geometry;
  if (g.tessellations.empty()) return;
  std::vector<SeedField> fields;
  for (const scenario::TessellationDefinition& t : g.tessellations) fields.push_back(make_seed_field(t, g.domain));
  geometry::BlockNetwork& net = model.network;
  std::vector<Polygon> blocks;
  std::vector<std::vector<int>> edge_fractures, edge_bonds;
  std::vector<int> bond_types;
  int tessellated = 0;
  for (std::size_t b = 0; b < net.blocks.size(); ++b) {
    const Polygon& block = net.blocks[b];
    const Point c = geometry::centroid(block);
    std::size_t k = 0;
    while (k < g.tessellations.size() && !g.tessellations[k].region.empty() && !geometry::contains(g.tessellations[k].region, c)) ++k;
    const std::vector<Point> seeds =
        k < g.tessellations.size()
            ? geometry::select_seeds(block, fields[k].near(geometry::bounding_box(block)), 0.2 * g.tessellations[k].size)
            : std::vector<Point>{};
    if (seeds.size() < 2) {  // not tessellated, or too small to be
      blocks.push_back(block);
      edge_fractures.push_back(net.edge_fractures[b]);
      edge_bonds.push_back(std::vector<int>(block.size(), -1));
      continue;
    }
    const scenario::TessellationDefinition& t = g.tessellations[k];
    geometry::Tessellation parts;
    try {
      parts = geometry::tessellate_convex(block, seeds, t.size, t.kind);
    } catch (const std::invalid_argument& e) {
      throw scenario::ScenarioError({{s.file.string(), t.line, "geometry.tessellate",
                                      fmt::format("block {} (centroid ({:g}, {:g})): {}; sub-blocks are made of convex "
                                                  "blocks only (not yet of others)",
                                                  b, c.x, c.y, e.what())}});
    }
    ++tessellated;
    const int type = std::max(0, s.joint_type_index(t.joint.name));
    // Each face between two sub-blocks once: the bond id given by the lower-numbered side.
    std::vector<std::vector<int>> ids(parts.cells.size());
    for (std::size_t p = 0; p < parts.cells.size(); ++p) ids[p].assign(parts.cells[p].size(), -1);
    for (std::size_t p = 0; p < parts.cells.size(); ++p)
      for (std::size_t e = 0; e < parts.cells[p].size(); ++e) {
        const int other = parts.edge_sources[p][e];
        if (other <= static_cast<int>(p)) continue;
        const std::vector<int>& back = parts.edge_sources[static_cast<std::size_t>(other)];
        const auto f = static_cast<std::size_t>(std::find(back.begin(), back.end(), static_cast<int>(p)) - back.begin());
        ids[p][e] = ids[static_cast<std::size_t>(other)][f] = static_cast<int>(bond_types.size());
        bond_types.push_back(type);
      }
    for (std::size_t p = 0; p < parts.cells.size(); ++p) {
      std::vector<int> fractures;
      for (int source : parts.edge_sources[p])
        fractures.push_back(source < 0 ? net.edge_fractures[b][static_cast<std::size_t>(-1 - source)] : -1);
      blocks.push_back(std::move(parts.cells[p]));
      edge_fractures.push_back(std::move(fractures));
      edge_bonds.push_back(std::move(ids[p]));
    }
  }
  net.blocks = std::move(blocks);
  net.edge_fractures = std::move(edge_fractures);
  model.edge_bonds = std::move(edge_bonds);
  model.bond_types = std::move(bond_types);
  model.summary += fmt::format(", {} of them tessellated into {} sub-blocks with {} bonds", tessellated,
                               net.blocks.size(), model.bond_types.size());
}

}  // namespace hydrodda::run
