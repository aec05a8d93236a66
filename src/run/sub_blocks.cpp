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

// The first table whose region holds p (a table without one holds every point); −1: none.
int first_table_holding(const std::vector<scenario::TessellationDefinition>& tables, Point p) {
  for (std::size_t k = 0; k < tables.size(); ++k)
    if (tables[k].region.empty() || geometry::contains(tables[k].region, p)) return static_cast<int>(k);
  return -1;
}

// Every table's cracks and paths with their seeds; a crack that lies on a path takes the
// path's faces and has no seeds of its own (two rows of seeds along one line would make
// slivers). Its broken faces are those whose middle lies on it.
struct Crack {
  geometry::Segment2 segment;
  geometry::CrackSeeds seeds;
  double margin = 0.0;  // from a block's edge, 0.2 of its table's size
  bool broken = true;   // a crack; false: a path, its bonds intact
};

bool lies_on_path(const geometry::Segment2& crack, const Crack& path) {
  const double tolerance = 1e-6 * path.seeds.spacing;
  return geometry::distance_to_segment(crack.from, path.segment.from, path.segment.to) <= tolerance &&
         geometry::distance_to_segment(crack.to, path.segment.from, path.segment.to) <= tolerance;
}

std::vector<Crack> make_cracks(const std::vector<scenario::TessellationDefinition>& tables) {
  std::vector<Crack> paths;
  for (const scenario::TessellationDefinition& t : tables)
    for (const scenario::Segment& c : t.paths) {
      const geometry::Segment2 segment{c.from, c.to};
      paths.push_back({segment, geometry::make_crack_seeds(segment, t.size), 0.2 * t.size, false});
    }
  std::vector<Crack> cracks;
  for (const scenario::TessellationDefinition& t : tables)
    for (const scenario::Segment& c : t.cracks) {
      const geometry::Segment2 segment{c.from, c.to};
      Crack crack{segment, geometry::make_crack_seeds(segment, t.size), 0.2 * t.size, true};
      for (const Crack& path : paths)
        if (lies_on_path(segment, path)) crack.seeds.seeds.clear();
      cracks.push_back(std::move(crack));
    }
  cracks.insert(cracks.end(), paths.begin(), paths.end());
  return cracks;
}

// The seeds of one block: of each table's jittered grid, those in the block (clear of its edges
// by 0.2 of the table's size) where that table is the first whose region holds them and no
// crack is near, and not within the table's size of a reflex corner of the block, whose pair
// of seeds takes their place (geometry::make_reflex_corner_seeds: the corner a node of two
// cells, none wrapping round it to be split there into a sliver); then every crack's pairs in
// the block. And the smallest size among them.
std::pair<std::vector<Point>, double> gather_seeds(const std::vector<scenario::TessellationDefinition>& tables,
                                                   const std::vector<SeedField>& fields, const std::vector<Crack>& cracks,
                                                   const Polygon& block) {
  std::vector<Point> seeds;
  double smallest = 0.0;
  const auto take_size = [&](double size) { smallest = smallest > 0.0 ? std::min(smallest, size) : size; };
  const auto near_crack = [&](Point p) {
    return std::any_of(cracks.begin(), cracks.end(),
                       [&](const Crack& c) { return geometry::lies_near_crack(p, c.segment, c.seeds.spacing); });
  };
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const std::size_t before = seeds.size();
    const double size = tables[k].size;
    std::vector<geometry::ReflexCornerSeeds> corners;
    for (const geometry::ReflexCornerSeeds& c : geometry::make_reflex_corner_seeds(block, size, 0.2 * size))
      if (std::all_of(c.seeds.begin(), c.seeds.end(),
                      [&](Point p) { return first_table_holding(tables, p) == static_cast<int>(k) && !near_crack(p); }))
        corners.push_back(c);
    for (Point p : geometry::select_seeds(block, fields[k].near(geometry::bounding_box(block)), 0.2 * size)) {
      if (first_table_holding(tables, p) != static_cast<int>(k) || near_crack(p)) continue;
      if (std::any_of(corners.begin(), corners.end(),
                      [&](const geometry::ReflexCornerSeeds& c) { return geometry::distance(p, c.corner) < size; }))
        continue;
      seeds.push_back(p);
    }
    for (const geometry::ReflexCornerSeeds& c : corners) seeds.insert(seeds.end(), c.seeds.begin(), c.seeds.end());
    if (seeds.size() > before) take_size(tables[k].size);
  }
  for (const Crack& c : cracks) {
    const std::vector<Point> in_block = geometry::select_seeds(block, c.seeds.seeds, c.margin);
    seeds.insert(seeds.end(), in_block.begin(), in_block.end());
    if (!in_block.empty()) take_size(c.seeds.spacing);
  }
  return {std::move(seeds), smallest};
}

// The edge of sub-block p's neighbour across edge e that faces it there: the one with the same
// ends, run the other way (two sub-blocks beside a reflex corner may meet along two faces).
std::size_t face_back(const geometry::Tessellation& parts, std::size_t p, std::size_t e) {
  const auto other = static_cast<std::size_t>(parts.edge_sources[p][e]);
  const Polygon& cell = parts.cells[p];
  const Polygon& across = parts.cells[other];
  for (std::size_t f = 0; f < across.size(); ++f)
    if (parts.edge_sources[other][f] == static_cast<int>(p) && across[f] == cell[(e + 1) % cell.size()] &&
        across[(f + 1) % across.size()] == cell[e])
      return f;
  const std::vector<int>& back = parts.edge_sources[other];
  return static_cast<std::size_t>(std::find(back.begin(), back.end(), static_cast<int>(p)) - back.begin());
}

}  // namespace

std::vector<int> find_crack_bonds(const scenario::Scenario& s, const std::vector<dda::BlockDefinition>& blocks) {
  std::vector<int> broken;
  if (!s.geometry) return broken;
  const std::vector<Crack> cracks = make_cracks(s.geometry->tessellations);
  if (cracks.empty()) return broken;
  for (const dda::BlockDefinition& block : blocks)
    for (std::size_t e = 0; e < block.edge_bonds.size(); ++e) {
      const int bond = block.edge_bonds[e];
      if (bond < 0) continue;
      const Point a = block.polygon[e], b = block.polygon[(e + 1) % block.polygon.size()];
      for (const Crack& c : cracks)
        if (c.broken && geometry::lies_on_crack(a, b, c.segment, 1e-6 * c.seeds.spacing)) broken.push_back(bond);
    }
  std::sort(broken.begin(), broken.end());
  broken.erase(std::unique(broken.begin(), broken.end()), broken.end());
  return broken;
}

void tessellate_blocks(const scenario::Scenario& s, ModelGeometry& model) {
  const scenario::GeometryDefinition& g = *s.geometry;
  if (g.tessellations.empty()) return;
  std::vector<SeedField> fields;
  for (const scenario::TessellationDefinition& t : g.tessellations) fields.push_back(make_seed_field(t, g.domain));
  const std::vector<Crack> cracks = make_cracks(g.tessellations);
  geometry::BlockNetwork& net = model.network;
  std::vector<Polygon> blocks;
  std::vector<std::vector<int>> edge_fractures, edge_bonds;
  std::vector<int> bond_types;
  int zone_faces = 0;
  int tessellated = 0;
  for (std::size_t b = 0; b < net.blocks.size(); ++b) {
    const Polygon& block = net.blocks[b];
    const Point c = geometry::centroid(block);
    std::size_t k = 0;
    while (k < g.tessellations.size() && !g.tessellations[k].region.empty() && !geometry::contains(g.tessellations[k].region, c)) ++k;
    const auto [seeds, size] = k < g.tessellations.size() ? gather_seeds(g.tessellations, fields, cracks, block)
                                                           : std::pair<std::vector<Point>, double>{};
    if (seeds.size() < 2) {  // not tessellated, or too small to be
      blocks.push_back(block);
      edge_fractures.push_back(net.edge_fractures[b]);
      edge_bonds.push_back(std::vector<int>(block.size(), -1));
      continue;
    }
    const scenario::TessellationDefinition& t = g.tessellations[k];
    geometry::Tessellation parts;
    try {
      // Voronoi cells are zoned: fanned into triangles as `triangles` are, their faces within a
      // cell zone faces that hold for good (a uniform-strain polygon bonded along its six or so
      // faces locks, docs/dda.md, "Bonds").
      parts = geometry::tessellate(block, seeds, size, geometry::TessellationKind::triangles);
    } catch (const std::invalid_argument& e) {
      throw scenario::ScenarioError({{s.file.string(), t.line, "geometry.tessellate",
                                      fmt::format("block {} (centroid ({:g}, {:g})): {}", b, c.x, c.y, e.what())}});
    }
    ++tessellated;
    const int type = std::max(0, s.joint_type_index(t.joint.name));
    // Each face between two sub-blocks once: the bond id given by the lower-numbered side; a
    // zone face k is −2 − k (dda::BlockDefinition::edge_bonds).
    const bool zoned = t.kind == geometry::TessellationKind::voronoi;
    std::vector<std::vector<int>> ids(parts.cells.size());
    for (std::size_t p = 0; p < parts.cells.size(); ++p) ids[p].assign(parts.cells[p].size(), -1);
    for (std::size_t p = 0; p < parts.cells.size(); ++p)
      for (std::size_t e = 0; e < parts.cells[p].size(); ++e) {
        const int other = parts.edge_sources[p][e];
        if (other <= static_cast<int>(p)) continue;
        const std::size_t f = face_back(parts, p, e);
        const bool zone = zoned && parts.cell_of[p] == parts.cell_of[static_cast<std::size_t>(other)];
        ids[p][e] = ids[static_cast<std::size_t>(other)][f] =
            zone ? -2 - zone_faces++ : static_cast<int>(bond_types.size());
        if (!zone) bond_types.push_back(type);
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
  if (zone_faces > 0) model.summary += fmt::format(" ({} faces within zoned Voronoi cells besides)", zone_faces);
}

geometry::BlockNetwork network_with_bond_faces(const ModelGeometry& model) {
  geometry::BlockNetwork network = model.network;
  const int first = static_cast<int>(model.traces.size());
  std::vector<char> listed(model.bond_types.size(), 0);
  for (std::size_t b = 0; b < model.edge_bonds.size(); ++b) {
    const Polygon& block = network.blocks[b];
    for (std::size_t e = 0; e < model.edge_bonds[b].size(); ++e) {
      const int bond = model.edge_bonds[b][e];
      if (bond < 0) continue;  // a zone face (−2 − k) is no flow path
      network.edge_fractures[b][e] = first + bond;
      if (listed[static_cast<std::size_t>(bond)]) continue;
      listed[static_cast<std::size_t>(bond)] = 1;
      network.faces.push_back({{block[e], block[(e + 1) % block.size()]}, first + bond});
    }
  }
  return network;
}

}  // namespace hydrodda::run
