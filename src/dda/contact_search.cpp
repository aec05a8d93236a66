#include "dda/contact_search.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "dda/array_growth.hpp"
#include "numerics/parallel.hpp"

namespace hydrodda::dda {

namespace {

// Below some thousand pairs a half takes tens of microseconds, and waking a second thread
// costs as much as it saves.
bool worth_two_threads(std::size_t pairs) { return pairs >= 1000; }

}  // namespace

ContactSearch::ContactSearch(double distance, double skin, double kept_depth)
    : distance_(distance), skin_(skin), kept_depth_(kept_depth) {
  if (!(distance >= 0.0) || !(skin >= 0.0))
    throw std::invalid_argument("contact search: the contact distance and the skin must be ≥ 0");
}

void ContactSearch::make_lists(std::span<const std::span<const geometry::Point>> polygons,
                               std::span<const char> fixed) {
  const double reach = contact_reach(distance_) + skin_;
  boxes_.clear();
  for (std::span<const geometry::Point> p : polygons) boxes_.push_back(geometry::bounding_box(p));
  find_block_pairs(boxes_, reach, fixed, pairs_);
  numerics::run_two_parts(worth_two_threads(pairs_.size()), [&](int part) {
    Half& half = halves_[part];
    half.pairs.clear();
    half.combinations.clear();
    const auto [begin, end] = numerics::half_range(part, pairs_.size());
    for (std::size_t p = begin; p < end; ++p) {
      const auto [a, b] = pairs_[p];
      ListedPair listed{a, b, half.combinations.size(), 0, 0};
      listed.middle = listed.first + find_vertex_edge_combinations(polygons[a], polygons[b], reach, half.combinations);
      listed.last = half.combinations.size();
      if (listed.last > listed.first) half.pairs.push_back(listed);
    }
  });
  listed_ = true;
  motion_ = 0.0;
  ++list_count_;
}

void ContactSearch::find(std::span<const std::span<const geometry::Point>> polygons,
                         std::span<const char> fixed, ContactCandidates& out) {
  if (!listed_ || 2.0 * motion_ > skin_) make_lists(polygons, fixed);
  const auto by_key = [](const ContactCandidate& x, const ContactCandidate& y) { return x.key < y.key; };
  numerics::run_two_parts(worth_two_threads(halves_[0].pairs.size() + halves_[1].pairs.size()), [&](int part) {
    Half& half = halves_[part];
    half.found.clear();
    for (const ListedPair& p : half.pairs) {
      const std::span<const VertexEdge> combinations(half.combinations.data() + p.first, p.last - p.first);
      find_pair_contacts(polygons[p.a], p.a, polygons[p.b], p.b, distance_, combinations, p.middle - p.first,
                         half.found, kept_depth_);
    }
    half.sort_found();
  });
  resize_for_overwrite(out, halves_[0].sorted.size() + halves_[1].sorted.size());
  std::merge(halves_[0].sorted.begin(), halves_[0].sorted.end(), halves_[1].sorted.begin(),
             halves_[1].sorted.end(), out.begin(), by_key);
}

void ContactSearch::Half::sort_found() {
  const std::size_t n = found.size();
  bool same = n == found_keys.size();
  for (std::size_t i = 0; same && i < n; ++i) same = found[i].key == found_keys[i];
  if (!same) {
    found_keys.resize(n);
    for (std::size_t i = 0; i < n; ++i) found_keys[i] = found[i].key;
    key_order.resize(n);
    std::iota(key_order.begin(), key_order.end(), 0);
    std::sort(key_order.begin(), key_order.end(), [&](int x, int y) { return found_keys[x] < found_keys[y]; });
  }
  resize_for_overwrite(sorted, n);
  for (std::size_t i = 0; i < n; ++i) sorted[i] = found[key_order[i]];
}

}  // namespace hydrodda::dda
