#include "geometry/block_merging.hpp"

#include <algorithm>
#include <bit>
#include <functional>
#include <queue>

namespace hydrodda::geometry {

std::size_t MergingBlocks::EdgeHash::operator()(const DirectedEdge& e) const {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (double v : {std::get<0>(e), std::get<1>(e), std::get<2>(e), std::get<3>(e)})
    h = (h ^ std::bit_cast<std::uint64_t>(v)) * 0x100000001b3ull;
  return static_cast<std::size_t>(h ^ (h >> 29));
}

// −0 and +0 are one coordinate, as == says: one key.
MergingBlocks::DirectedEdge MergingBlocks::directed(Point a, Point b) {
  return {a.x + 0.0, a.y + 0.0, b.x + 0.0, b.y + 0.0};
}

MergingBlocks::MergingBlocks(std::vector<MergeableBlock> blocks)
    : blocks_(std::move(blocks)), alive_(blocks_.size(), true) {
  std::size_t edges = 0;
  for (const MergeableBlock& b : blocks_) edges += b.polygon.size();
  owner_.reserve(edges);
  for (int id = 0; id < size(); ++id) own_edges(id, true);
}

void MergingBlocks::own_edges(int id, bool owned) {
  const Polygon& p = blocks_[static_cast<std::size_t>(id)].polygon;
  for (std::size_t e = 0; e < p.size(); ++e) {
    const DirectedEdge key = directed(p[e], p[(e + 1) % p.size()]);
    if (owned) owner_[key] = id;
    else owner_.erase(key);
  }
}

// The union of block k and its neighbour m along their shared chain, or empty when the shared
// edges are not one chain or the union is not simple. Its first `from_k` edges are k's.
std::optional<MergingBlocks::Union> MergingBlocks::unite(int k_id, int m_id) const {
  const MergeableBlock& k = block(k_id);
  const MergeableBlock& m = block(m_id);
  const auto shared_with = [&](const Polygon& p, int other) {  // per edge: its reverse is other's
    std::vector<bool> shared(p.size());
    for (std::size_t e = 0; e < p.size(); ++e) {
      const auto it = owner_.find(directed(p[(e + 1) % p.size()], p[e]));
      shared[e] = it != owner_.end() && it->second == other;
    }
    return shared;
  };
  const std::vector<bool> shared_k = shared_with(k.polygon, m_id), shared_m = shared_with(m.polygon, k_id);
  const std::size_t nk = k.polygon.size(), nm = m.polygon.size();
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
  Union u;
  // k's own edges from the chain's end round to its start ...
  std::size_t e = first;
  while (shared_k[e]) e = (e + 1) % nk;
  for (; !shared_k[e]; e = (e + 1) % nk) {
    u.block.polygon.push_back(k.polygon[e]);
    u.block.fractures.push_back(k.fractures[e]);
  }
  u.from_k = u.block.polygon.size();
  // ... then m's, from the chain's start round to its end.
  std::size_t g = 0;
  while (g < nm && !(m.polygon[g] == chain_start && !shared_m[g])) ++g;
  if (g == nm) return std::nullopt;
  for (std::size_t count = 0; !shared_m[g] && count < nm; g = (g + 1) % nm, ++count) {
    u.block.polygon.push_back(m.polygon[g]);
    u.block.fractures.push_back(m.fractures[g]);
  }
  const Polygon& p = u.block.polygon;
  if (p.size() < 3 || signed_area(p) <= 0.0 || find_self_intersection(p)) return std::nullopt;
  return u;
}

std::optional<int> MergingBlocks::merge_into_neighbour(int id) {
  // Each neighbour with its shared length, summed along the block's edges in order.
  const Polygon& p = blocks_[static_cast<std::size_t>(id)].polygon;
  std::vector<std::pair<int, double>> pieces;  // (neighbour, length of one shared edge)
  for (std::size_t e = 0; e < p.size(); ++e) {
    const Point a = p[e], b = p[(e + 1) % p.size()];
    const auto it = owner_.find(directed(b, a));
    if (it != owner_.end() && it->second != id) pieces.push_back({it->second, distance(a, b)});
  }
  std::stable_sort(pieces.begin(), pieces.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::pair<double, int>> order;  // (−shared length, neighbour)
  for (std::size_t k = 0; k < pieces.size();) {
    const int m = pieces[k].first;
    double shared = 0.0;
    for (; k < pieces.size() && pieces[k].first == m; ++k) shared += pieces[k].second;
    order.push_back({-shared, m});
    ++visits_;
  }
  std::sort(order.begin(), order.end());
  for (const auto& [minus_length, m] : order) {
    auto united = unite(id, m);
    if (!united) continue;
    // The edges k and m shared are gone, and k's others are the union's: m's others stay m's.
    const Polygon& q = blocks_[static_cast<std::size_t>(m)].polygon;
    for (std::size_t e = 0; e < q.size(); ++e) {
      const auto it = owner_.find(directed(q[(e + 1) % q.size()], q[e]));
      if (it != owner_.end() && it->second == id) owner_.erase(directed(q[e], q[(e + 1) % q.size()]));
    }
    own_edges(id, false);
    const Polygon& u = united->block.polygon;
    for (std::size_t e = 0; e < united->from_k; ++e) owner_[directed(u[e], u[(e + 1) % u.size()])] = m;
    blocks_[static_cast<std::size_t>(m)] = std::move(united->block);
    blocks_[static_cast<std::size_t>(id)] = {};
    alive_[static_cast<std::size_t>(id)] = false;
    return m;
  }
  return std::nullopt;
}

SliverCounts merge_slivers(MergingBlocks& blocks, double min_area) {
  // The queue holds (area, id, version); an entry whose block has since changed is stale.
  using Entry = std::tuple<double, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  std::vector<int> version(static_cast<std::size_t>(blocks.size()), 0);
  const auto offer = [&](int id) {
    const double a = signed_area(blocks.block(id).polygon);
    if (a < min_area) queue.push({a, id, version[static_cast<std::size_t>(id)]});
  };
  for (int id = 0; id < blocks.size(); ++id) offer(id);
  SliverCounts counts;
  while (!queue.empty()) {
    const auto [area, id, v] = queue.top();
    queue.pop();
    blocks.count_visit();
    if (!blocks.alive(id) || v != version[static_cast<std::size_t>(id)]) continue;
    const auto united = blocks.merge_into_neighbour(id);
    if (!united) {
      ++counts.unmerged;  // not offered again unless a merge into it changes it
      continue;
    }
    ++counts.merged;
    ++version[static_cast<std::size_t>(*united)];
    offer(*united);
  }
  return counts;
}

}  // namespace hydrodda::geometry
