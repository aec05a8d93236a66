#pragma once
// Merging the blocks of a cut into their neighbours, each merge local: who owns each directed
// edge is kept up to date, so a block finds its neighbours through its own edges (the cut
// gives neighbours the same vertices along a shared face), and the slivers wait in a queue
// by area. A merge costs what the block and its neighbours hold, not what the whole cut holds.

#include <cstdint>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

struct MergeableBlock {
  Polygon polygon;             // counter-clockwise
  std::vector<int> fractures;  // per edge (vertex k → k + 1): its fracture id, −1 on the domain boundary
};

// The blocks of a cut, each known by its id, its place in the cut's order. A union takes the
// id of the neighbour it merged into, so the ids of the blocks left keep the order a list
// would keep if the merged block were taken out and the union put in the neighbour's place.
class MergingBlocks {
 public:
  explicit MergingBlocks(std::vector<MergeableBlock> blocks);

  // Merges block `id` into a neighbour:
  //   the neighbour is the one it shares the longest boundary with (of equal ones, the lowest
  //   id), among those whose shared boundary is one chain of edges and whose union is simple;
  //   the union walks the block's own edges from the chain's end round to its start, then the
  //   neighbour's, so that every other edge and its fracture id are kept.
  // The union's id (the neighbour's), or empty when no neighbour can take the block.
  std::optional<int> merge_into_neighbour(int id);

  int size() const { return static_cast<int>(blocks_.size()); }  // ids given, merged ones too
  bool alive(int id) const { return alive_[static_cast<std::size_t>(id)]; }
  const MergeableBlock& block(int id) const { return blocks_[static_cast<std::size_t>(id)]; }
  // Blocks looked at so far: every neighbour a merge weighed (see merge_slivers too).
  long visits() const { return visits_; }
  void count_visit() { ++visits_; }

 private:
  using DirectedEdge = std::tuple<double, double, double, double>;
  struct EdgeHash {
    std::size_t operator()(const DirectedEdge& e) const;
  };
  struct Union {
    MergeableBlock block;
    std::size_t from_k = 0;  // its first edges, the merged block's
  };
  static DirectedEdge directed(Point a, Point b);
  void own_edges(int id, bool owned);
  std::optional<Union> unite(int k, int m) const;

  std::vector<MergeableBlock> blocks_;
  std::vector<bool> alive_;
  std::unordered_map<DirectedEdge, int, EdgeHash> owner_;  // looked up only, never iterated
  long visits_ = 0;
};

struct SliverCounts {
  int merged = 0;    // slivers merged into a neighbour
  int unmerged = 0;  // slivers no neighbour could take, left as they are
};

// Blocks below `min_area` merged, smallest first (of equal areas, the lowest id), until none
// is left or none of those left can be merged; a union still below it waits its turn again.
// One no neighbour can take is left as it is until a merge into it changes it. Each block
// taken from the queue counts as a visit.
SliverCounts merge_slivers(MergingBlocks& blocks, double min_area);

}  // namespace hydrodda::geometry
