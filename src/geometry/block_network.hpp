#pragma once
// From a domain and its fracture traces to the blocks a model starts with: the cut
// (domain_cutting.hpp), slivers merged into a neighbour, the initial aperture opened. Each
// block edge remembers the trace it lies on, for per-fracture results.

#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

// Where a trace came from: a fracture listed in the scenario, a joint of a generated set, or a
// row of a fractures file.
enum class TraceSource { listed, joint_set, file };
struct TraceOrigin {
  TraceSource source = TraceSource::listed;
  int set = -1;    // the joint set (0-based), for joint_set
  int number = 0;  // listed: index (0-based); joint_set: trace of the set (0-based); file: line
};

struct FractureTrace {
  Segment2 segment;
  TraceOrigin origin;
  int joint_type = 0;  // the joint type it is of (an index the caller keeps; 0: the default)
};

// A piece of a fracture between two blocks.
struct FractureFace {
  Segment2 segment;
  int fracture = 0;  // its fracture id
};

struct BlockNetworkRequest {
  Polygon domain;                      // counter-clockwise
  std::vector<FractureTrace> traces;   // a trace's index is its fracture id
  std::vector<Polygon> welded;
  double min_block_area = 0.0;         // m²; 0: 1% of the mean block area of the cut
  double aperture = 0.0;               // m, the initial aperture
};

struct BlockNetwork {
  std::vector<Polygon> blocks;  // counter-clockwise, shrunk by the aperture, in a deterministic order
  // Per block, per edge (vertex k → k + 1): the fracture id (index into the request's traces)
  // the edge lies on, −1 on the domain boundary.
  std::vector<std::vector<int>> edge_fractures;
  // The fracture faces between the blocks before the aperture opened them, each once, with
  // its fracture id: where the traces that remain run (mesh refinement, results per fracture).
  std::vector<FractureFace> faces;
  std::vector<int> dropped_from;  // fracture ids with a piece that cut nothing, ascending
  double min_block_area = 0.0;    // the threshold used (m²)
  int cut_blocks = 0;             // blocks the cut made, before merging
  int merged_small = 0;           // blocks below min_block_area, merged
  int merged_thin = 0;            // blocks the aperture would have turned inside out or halved, merged
  int unmerged_small = 0;         // blocks below min_block_area with no neighbour to merge into
  long merge_visits = 0;          // blocks the merges looked at: slivers taken from their queue, neighbours weighed
};

// Why no network could be made, and which input it is about.
class BlockNetworkError : public std::runtime_error {
 public:
  enum class Cause { aperture, fractures };
  BlockNetworkError(Cause cause, const std::string& message) : std::runtime_error(message), cause_(cause) {}
  Cause cause() const { return cause_; }

 private:
  Cause cause_;
};

// The merge of a block into its neighbour (block_merging.hpp):
//   the neighbour is the one it shares the longest boundary with (of equal ones, the first),
//   among those whose shared boundary is one chain of edges and whose union is simple;
//   the union walks the block's own edges from the chain's end round to its start, then the
//   neighbour's, so that every other edge and its fracture id are kept.
// Blocks below the minimum area are merged, smallest first (of equal ones, the first), until
// none is left (or none can be merged); then every block is shrunk by the aperture, and one
// the aperture would turn inside out or shrink to less than half its area is merged the same
// way and the shrink tried again. Each merge looks at the block and its neighbours only, so
// the whole takes time near-linear in the number of blocks. Throws BlockNetworkError when a block can be neither shrunk nor merged, or
// the traces make a block that touches itself.
BlockNetwork build_block_network(const BlockNetworkRequest& request);

}  // namespace hydrodda::geometry
