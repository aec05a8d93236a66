#include "geometry/block_network.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>
#include <tuple>

#include "geometry/block_merging.hpp"
#include "geometry/domain_cutting.hpp"

namespace hydrodda::geometry {

namespace {

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

std::vector<bool> fracture_faces(const MergeableBlock& b) {
  std::vector<bool> faces(b.fractures.size());
  for (std::size_t e = 0; e < faces.size(); ++e) faces[e] = b.fractures[e] >= 0;
  return faces;
}

// Every block shrunk by the aperture, in the order of their ids: one the aperture turns inside
// out, or shrinks to less than half, is merged and the union tried in its place (the lowest id
// not yet shrunk goes next, as a union can take an earlier id).
std::vector<std::optional<ShrunkBlock>> open_aperture(MergingBlocks& blocks, double aperture, int& merged_thin) {
  std::vector<std::optional<ShrunkBlock>> shrunk(static_cast<std::size_t>(blocks.size()));
  std::set<int> pending;
  for (int id = 0; id < blocks.size(); ++id)
    if (blocks.alive(id)) pending.insert(id);
  while (!pending.empty()) {
    const int id = *pending.begin();
    const MergeableBlock& block = blocks.block(id);
    if (aperture <= 0.0) {
      ShrunkBlock same{block.polygon, {}};
      for (std::size_t e = 0; e < block.polygon.size(); ++e) same.edges.push_back(static_cast<int>(e));
      shrunk[static_cast<std::size_t>(id)] = std::move(same);
      pending.erase(pending.begin());
      continue;
    }
    auto s = shrink_block(block.polygon, fracture_faces(block), aperture);
    if (s && signed_area(s->polygon) >= 0.5 * signed_area(block.polygon)) {
      shrunk[static_cast<std::size_t>(id)] = std::move(s);
      pending.erase(pending.begin());
      continue;
    }
    const Point where = centroid(block.polygon);
    const double area = signed_area(block.polygon);
    const auto united = blocks.merge_into_neighbour(id);
    if (!united)
      throw BlockNetworkError(BlockNetworkError::Cause::aperture,
                              "the block at " + describe_point(where) + ", of area " + describe_number(area) +
                                  " m2, is too thin for the initial aperture and has no neighbour to merge into");
    ++merged_thin;
    pending.erase(pending.begin());
    shrunk[static_cast<std::size_t>(*united)].reset();
    pending.insert(*united);
  }
  return shrunk;
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
  std::vector<MergeableBlock> cut_blocks;
  double total_area = 0.0;
  for (std::size_t b = 0; b < cut.blocks.size(); ++b) {
    if (auto crossing = find_self_intersection(cut.blocks[b]))
      throw BlockNetworkError(BlockNetworkError::Cause::fractures,
                              "the fractures make a block that touches itself near " +
                                  describe_point(cut.blocks[b][crossing->first]) +
                                  " (traces meeting at one point from several sides): move one of them");
    total_area += signed_area(cut.blocks[b]);
    cut_blocks.push_back({std::move(cut.blocks[b]), std::move(cut.edge_fractures[b])});
  }
  network.min_block_area = request.min_block_area > 0.0 || cut_blocks.empty()
                               ? request.min_block_area
                               : 0.01 * total_area / static_cast<double>(cut_blocks.size());

  MergingBlocks merging(std::move(cut_blocks));
  const SliverCounts slivers = merge_slivers(merging, network.min_block_area);
  network.merged_small = slivers.merged;
  network.unmerged_small = slivers.unmerged;
  std::vector<std::optional<ShrunkBlock>> shrunk = open_aperture(merging, request.aperture, network.merged_thin);
  network.merge_visits = merging.visits();

  std::vector<int> ids;  // the blocks left, in the cut's order
  for (int id = 0; id < merging.size(); ++id)
    if (merging.alive(id)) ids.push_back(id);
  // Deterministic order: by the centroid of the unshrunk block, bottom to top, then left to right.
  std::vector<std::size_t> order(ids.size());
  std::vector<Point> centroids;
  for (std::size_t b = 0; b < ids.size(); ++b) {
    order[b] = b;
    centroids.push_back(centroid(merging.block(ids[b]).polygon));
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Point ca = centroids[a], cb = centroids[b];
    return ca.y != cb.y ? ca.y < cb.y : (ca.x != cb.x ? ca.x < cb.x : a < b);
  });
  std::set<DirectedEdge> listed_faces;
  for (std::size_t b : order) {
    const MergeableBlock& block = merging.block(ids[b]);
    const Polygon& p = block.polygon;
    for (std::size_t e = 0; e < p.size(); ++e) {
      const Point a = p[e], c = p[(e + 1) % p.size()];
      if (block.fractures[e] >= 0 && !listed_faces.contains(directed(c, a))) {
        listed_faces.insert(directed(a, c));
        network.faces.push_back({{a, c}, block.fractures[e]});
      }
    }
  }
  for (std::size_t b : order) {
    ShrunkBlock& opened = *shrunk[static_cast<std::size_t>(ids[b])];
    std::vector<int> fractures;
    for (int e : opened.edges) fractures.push_back(merging.block(ids[b]).fractures[e]);
    network.blocks.push_back(std::move(opened.polygon));
    network.edge_fractures.push_back(std::move(fractures));
  }
  return network;
}

}  // namespace hydrodda::geometry
