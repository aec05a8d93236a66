#include "geometry/block_network.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>
#include <tuple>

#include "geometry/domain_cutting.hpp"

namespace hydrodda::geometry {

namespace {

struct Block {
  Polygon polygon;
  std::vector<int> fractures;          // per edge
  std::optional<ShrunkBlock> shrunk;   // once the aperture has been opened
};

using DirectedEdge = std::tuple<double, double, double, double>;
DirectedEdge directed(Point a, Point b) { return {a.x, a.y, b.x, b.y}; }

std::string describe_point(Point p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.6g, %.6g)", p.x, p.y);
  return text;
}

std::string describe_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// The union of block k and its neighbour m along their shared chain, or empty when the shared
// edges are not one chain or the union is not simple. The cut gives neighbours the same
// vertices along a shared face, so shared edges are the same points in reverse.
std::optional<Block> unite(const Block& k, const Block& m) {
  std::set<DirectedEdge> edges_of_k;
  const std::size_t nk = k.polygon.size(), nm = m.polygon.size();
  for (std::size_t e = 0; e < nk; ++e) edges_of_k.insert(directed(k.polygon[e], k.polygon[(e + 1) % nk]));
  std::set<DirectedEdge> edges_of_m;
  for (std::size_t e = 0; e < nm; ++e) edges_of_m.insert(directed(m.polygon[e], m.polygon[(e + 1) % nm]));
  std::vector<bool> shared_k(nk), shared_m(nm);
  for (std::size_t e = 0; e < nk; ++e) shared_k[e] = edges_of_m.contains(directed(k.polygon[(e + 1) % nk], k.polygon[e]));
  for (std::size_t e = 0; e < nm; ++e) shared_m[e] = edges_of_k.contains(directed(m.polygon[(e + 1) % nm], m.polygon[e]));
  // One chain: exactly one place where a shared edge follows one that is not.
  int starts = 0;
  std::size_t first = 0;
  for (std::size_t e = 0; e < nk; ++e)
    if (shared_k[e] && !shared_k[(e + nk - 1) % nk]) {
      ++starts;
      first = e;
    }
  if (starts != 1) return std::nullopt;
  const Point chain_start = k.polygon[first];
  Block u;
  // k's own edges from the chain's end round to its start ...
  std::size_t e = first;
  while (shared_k[e]) e = (e + 1) % nk;
  for (; !shared_k[e]; e = (e + 1) % nk) {
    u.polygon.push_back(k.polygon[e]);
    u.fractures.push_back(k.fractures[e]);
  }
  // ... then m's, from the chain's start round to its end.
  std::size_t g = 0;
  while (g < nm && !(m.polygon[g] == chain_start && !shared_m[g])) ++g;
  if (g == nm) return std::nullopt;
  for (std::size_t count = 0; !shared_m[g] && count < nm; g = (g + 1) % nm, ++count) {
    u.polygon.push_back(m.polygon[g]);
    u.fractures.push_back(m.fractures[g]);
  }
  if (u.polygon.size() < 3 || signed_area(u.polygon) <= 0.0 || find_self_intersection(u.polygon)) return std::nullopt;
  return u;
}

// Merges blocks[k] into the neighbour it shares the longest boundary with (see the header);
// whether it could.
bool merge_into_neighbour(std::vector<Block>& blocks, std::size_t k) {
  // Neighbours share an edge, so their boxes overlap: the others are passed over at a glance.
  const Polygon& p = blocks[k].polygon;
  const Box box = bounding_box(p);
  std::vector<std::pair<double, int>> order;  // (−shared length, neighbour)
  for (std::size_t m = 0; m < blocks.size(); ++m) {
    const Polygon& q = blocks[m].polygon;
    if (m == k || !box.overlaps(bounding_box(q))) continue;
    double shared = 0.0;
    for (std::size_t e = 0; e < p.size(); ++e) {
      const Point a = p[e], b = p[(e + 1) % p.size()];
      for (std::size_t f = 0; f < q.size(); ++f)
        if (q[f] == b && q[(f + 1) % q.size()] == a) shared += distance(a, b);
    }
    if (shared > 0.0) order.push_back({-shared, static_cast<int>(m)});
  }
  std::sort(order.begin(), order.end());
  for (const auto& [minus_length, m] : order) {
    auto united = unite(blocks[k], blocks[m]);
    if (!united) continue;
    blocks[m] = std::move(*united);
    blocks.erase(blocks.begin() + static_cast<std::ptrdiff_t>(k));
    return true;
  }
  return false;
}

std::vector<bool> fracture_faces(const Block& b) {
  std::vector<bool> faces(b.fractures.size());
  for (std::size_t e = 0; e < faces.size(); ++e) faces[e] = b.fractures[e] >= 0;
  return faces;
}

}  // namespace

BlockNetwork build_block_network(const BlockNetworkRequest& request) {
  std::vector<Segment2> segments;
  segments.reserve(request.traces.size());
  for (const FractureTrace& t : request.traces) segments.push_back(t.segment);
  CutResult cut = cut_domain(request.domain, segments, request.welded);

  BlockNetwork network;
  network.dropped_from = std::move(cut.dropped_from);
  network.cut_blocks = static_cast<int>(cut.blocks.size());
  std::vector<Block> blocks;
  double total_area = 0.0;
  for (std::size_t b = 0; b < cut.blocks.size(); ++b) {
    if (auto crossing = find_self_intersection(cut.blocks[b]))
      throw BlockNetworkError(BlockNetworkError::Cause::fractures,
                              "the fractures make a block that touches itself near " +
                                  describe_point(cut.blocks[b][crossing->first]) +
                                  " (traces meeting at one point from several sides): move one of them");
    total_area += signed_area(cut.blocks[b]);
    blocks.push_back({std::move(cut.blocks[b]), std::move(cut.edge_fractures[b]), std::nullopt});
  }
  network.min_block_area = request.min_block_area > 0.0 || blocks.empty()
                               ? request.min_block_area
                               : 0.01 * total_area / static_cast<double>(blocks.size());

  // Slivers, smallest first; one that cannot be merged is left as it is.
  std::vector<Polygon> unmergeable;
  for (;;) {
    std::optional<std::size_t> smallest;
    double smallest_area = network.min_block_area;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      const double a = signed_area(blocks[b].polygon);
      if (a < smallest_area && std::find(unmergeable.begin(), unmergeable.end(), blocks[b].polygon) == unmergeable.end()) {
        smallest = b;
        smallest_area = a;
      }
    }
    if (!smallest) break;
    if (merge_into_neighbour(blocks, *smallest)) ++network.merged_small;
    else unmergeable.push_back(blocks[*smallest].polygon);
  }
  network.unmerged_small = static_cast<int>(unmergeable.size());

  // The aperture: a block it turns inside out, or shrinks to less than half, is merged and the
  // union tried in its place.
  if (request.aperture > 0.0) {
    for (std::size_t b = 0; b < blocks.size();) {
      Block& block = blocks[b];
      if (!block.shrunk) {
        auto s = shrink_block(block.polygon, fracture_faces(block), request.aperture);
        if (s && signed_area(s->polygon) >= 0.5 * signed_area(block.polygon)) block.shrunk = std::move(s);
      }
      if (block.shrunk) {
        ++b;
        continue;
      }
      const Point where = centroid(block.polygon);
      const double area = signed_area(block.polygon);
      if (!merge_into_neighbour(blocks, b))
        throw BlockNetworkError(BlockNetworkError::Cause::aperture,
                                "the block at " + describe_point(where) + ", of area " + describe_number(area) +
                                    " m2, is too thin for the initial aperture and has no neighbour to merge into");
      ++network.merged_thin;
      b = 0;  // the union took a neighbour's place, earlier or later: look again (those done are kept)
    }
  } else {
    for (Block& block : blocks) {
      ShrunkBlock same{block.polygon, {}};
      for (std::size_t e = 0; e < block.polygon.size(); ++e) same.edges.push_back(static_cast<int>(e));
      block.shrunk = std::move(same);
    }
  }

  // Deterministic order: by the centroid of the unshrunk block, bottom to top, then left to right.
  std::vector<std::size_t> order(blocks.size());
  std::vector<Point> centroids;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    order[b] = b;
    centroids.push_back(centroid(blocks[b].polygon));
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Point ca = centroids[a], cb = centroids[b];
    return ca.y != cb.y ? ca.y < cb.y : (ca.x != cb.x ? ca.x < cb.x : a < b);
  });
  std::set<DirectedEdge> listed_faces;
  for (std::size_t b : order) {
    const Polygon& p = blocks[b].polygon;
    for (std::size_t e = 0; e < p.size(); ++e) {
      const Point a = p[e], c = p[(e + 1) % p.size()];
      if (blocks[b].fractures[e] >= 0 && !listed_faces.contains(directed(c, a))) {
        listed_faces.insert(directed(a, c));
        network.faces.push_back({{a, c}, blocks[b].fractures[e]});
      }
    }
  }
  for (std::size_t b : order) {
    ShrunkBlock& shrunk = *blocks[b].shrunk;
    std::vector<int> fractures;
    for (int e : shrunk.edges) fractures.push_back(blocks[b].fractures[e]);
    network.blocks.push_back(std::move(shrunk.polygon));
    network.edge_fractures.push_back(std::move(fractures));
  }
  return network;
}

}  // namespace hydrodda::geometry
