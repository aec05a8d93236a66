#pragma once
// The contact candidates of a set of moving polygons, step after step.
//
// The broad phase (block pairs) and, within each pair, the vertex–edge combinations near
// enough to become contacts are listed with a skin added to the contact distance, and the
// lists are kept while no vertex has moved more than half the skin since they were made:
// neighbour lists (Verlet 1967; Allen & Tildesley, Computer Simulation of Liquids, 2nd ed.
// 2017, §5.3). A combination left out was farther than the contact distance plus the skin
// from its edge; a vertex and the edge's two ends each moving at most half the skin, it is
// still farther than the contact distance, and no contact (contact_reach). So a step with
// kept lists tests only what it could find, and finds exactly what a search of all pairs
// finds.
//
// Pseudocode of find():
//   if no lists, or the motion since they were made exceeds skin / 2:
//     pairs ← blocks whose boxes, grown by distance + skin, overlap (find_block_pairs)
//     for each pair, the combinations within distance + skin (find_vertex_edge_combinations)
//     motion ← 0
//   candidates ← the vertex–edge test on each listed combination (find_pair_contacts)

#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "dda/contact_detection.hpp"

namespace hydrodda::dda {

class ContactSearch {
 public:
  // Contacts within `distance`, listed with `skin` (≥ 0) more; `kept_depth` as find_pair_contacts'.
  ContactSearch(double distance, double skin, double kept_depth = kNoCornerMemory);

  // The candidates among `polygons` as they are now, sorted by key, into `out` (its old
  // contents replaced). fixed[i]: polygon i never moves; pairs of two such are left out. The
  // same polygons, in the same order, call after call.
  void find(std::span<const std::span<const geometry::Point>> polygons, std::span<const char> fixed,
            ContactCandidates& out);
  // No vertex has moved more than `displacement` since the last find().
  void add_motion(double displacement) { motion_ += displacement; }
  // The polygons changed in some other way: the next find() lists afresh.
  void forget() { listed_ = false; }
  // How many times the lists have been made.
  long list_count() const { return list_count_; }

 private:
  // A pair's combinations: [first, middle) a's vertices on b's edges, [middle, last) b's on a's.
  struct ListedPair {
    int a = 0, b = 0;
    std::size_t first = 0, middle = 0, last = 0;
  };
  // The pairs are listed and searched in two halves, side by side on two threads where there
  // are two; each half's candidates sorted, the halves merged (keys are unique).
  struct Half {
    std::vector<ListedPair> pairs;
    std::vector<VertexEdge> combinations;
    ContactCandidates found;   // in the order the lists give them
    ContactCandidates sorted;  // by key
    // The keys found last time, in the lists' order, and the order that sorted them: while
    // the lists are kept and no contact comes or goes, each search finds the same keys in the
    // same order, and sorting them again would only repeat that order.
    std::vector<ContactKey> found_keys;
    std::vector<int> key_order;
    void sort_found();
  };
  void make_lists(std::span<const std::span<const geometry::Point>> polygons, std::span<const char> fixed);

  double distance_;
  double skin_;
  double kept_depth_;
  bool listed_ = false;
  double motion_ = 0.0;
  long list_count_ = 0;
  std::vector<geometry::Box> boxes_;
  std::vector<std::pair<int, int>> pairs_;
  std::array<Half, 2> halves_;
};

}  // namespace hydrodda::dda
