#include "dda/linear_solver.hpp"

#include <algorithm>
#include <array>

#include "numerics/parallel.hpp"

namespace hydrodda::dda {

namespace {

// find_changed_terms on now[i, i_end) and before[j, j_end), appending to added and removed;
// false as soon as they hold more than `limit` between them.
bool walk_changed_terms(const RankOneTerms& now, std::size_t i, std::size_t i_end, const RankOneTerms& before,
                        std::size_t j, std::size_t j_end, std::size_t limit, RankOneTerms& added,
                        RankOneTerms& removed) {
  // One walk over both sorted lists, one three-way comparison a step: the lists are long
  // (two springs a contact) and nearly the same.
  const auto over_limit = [&] { return added.size() + removed.size() > limit; };
  while (i < i_end && j < j_end) {
    const auto order = now[i].id <=> before[j].id;
    if (order == 0) {
      ++i;
      ++j;
      continue;
    }
    if (order < 0)
      added.push_back(now[i++]);
    else
      removed.push_back(before[j++]);
    if (over_limit()) return false;
  }
  for (; i < i_end && !over_limit(); ++i) added.push_back(now[i]);
  for (; j < j_end && !over_limit(); ++j) removed.push_back(before[j]);
  return !over_limit();
}

// Below this many springs a walk takes tens of microseconds, what waking a second thread
// can cost.
bool worth_two_threads(std::size_t terms) { return terms >= 10000; }

}  // namespace

bool find_changed_terms(const RankOneTerms& now, const RankOneTerms& before, std::size_t limit,
                        RankOneTerms& added, RankOneTerms& removed) {
  added.clear();
  removed.clear();
  // Two walks side by side: now's first half against the terms of `before` that sort before
  // now's middle term, and the rest against the rest. The two halves' changes, in turn, are
  // the changes in id order, the same on one thread or two.
  const std::size_t middle = now.size() / 2;
  const std::size_t before_middle =
      middle == now.size() ? before.size()
                           : static_cast<std::size_t>(
                                 std::lower_bound(before.begin(), before.end(), now[middle].id,
                                                  [](const RankOneTerm& t, const std::array<int, 5>& id) { return t.id < id; }) -
                                 before.begin());
  std::array<RankOneTerms, 2> second;  // the second half's changes: added, removed
  std::array<bool, 2> found{};
  numerics::run_two_parts(worth_two_threads(now.size() + before.size()), [&](int part) {
    found[part] = part == 0 ? walk_changed_terms(now, 0, middle, before, 0, before_middle, limit, added, removed)
                            : walk_changed_terms(now, middle, now.size(), before, before_middle, before.size(),
                                                 limit, second[0], second[1]);
  });
  if (!found[0] || !found[1]) return false;
  added.insert(added.end(), second[0].begin(), second[0].end());
  removed.insert(removed.end(), second[1].begin(), second[1].end());
  return added.size() + removed.size() <= limit;
}

std::vector<int> order_by_minimum_degree(const BlockMatrix& base, const RankOneTerms& springs) {
  // The pattern alone: the ordering reads the pairs, and a pair listed twice is the same edge.
  BlockMatrix pattern;
  pattern.block_count = base.block_count;
  pattern.pairs = base.pairs;
  for (const RankOneTerm& t : springs)
    if (t.joins_two_blocks())
      pattern.pairs.emplace_back(std::min(t.block_a, t.block_b), std::max(t.block_a, t.block_b));
  return order_by_minimum_degree(pattern);
}

bool all_finite(const BlockMatrix& base, const RankOneTerms& springs) {
  return base.all_finite() && std::all_of(springs.begin(), springs.end(), [](const RankOneTerm& t) {
           return t.w_a.allFinite() && t.w_b.allFinite();
         });
}

BlockMatrix add_springs(const BlockMatrix& base, const RankOneTerms& springs) {
  BlockMatrix a;
  add_springs(base, springs, a);
  return a;
}

void add_springs(const BlockMatrix& base, const RankOneTerms& springs, BlockMatrix& a) {
  const int n = base.block_count;
  a.block_count = n;
  a.diagonal.assign(base.diagonal.begin(), base.diagonal.end());
  a.pairs.clear();
  // The pairs (column, row), row > column, of the base and of the springs that join two
  // blocks, bucketed by column (a counting sort: a block touches a handful of others), each
  // column's rows then sorted and made unique.
  std::vector<int> start(n + 1, 0);
  for (const auto& [column, row] : base.pairs) ++start[column + 1];
  for (const RankOneTerm& t : springs)
    if (t.joins_two_blocks()) ++start[std::min(t.block_a, t.block_b) + 1];
  for (int c = 0; c < n; ++c) start[c + 1] += start[c];
  std::vector<int> rows(start[n]);
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (const auto& [column, row] : base.pairs) rows[next[column]++] = row;
    for (const RankOneTerm& t : springs)
      if (t.joins_two_blocks()) rows[next[std::min(t.block_a, t.block_b)]++] = std::max(t.block_a, t.block_b);
  }
  std::vector<int> first_pair(n + 1, 0);  // a.pairs of column c: [first_pair[c], first_pair[c + 1])
  for (int c = 0; c < n; ++c) {
    const auto begin = rows.begin() + start[c], end = rows.begin() + start[c + 1];
    std::sort(begin, end);
    first_pair[c] = static_cast<int>(a.pairs.size());
    for (auto r = begin; r != end; ++r)
      if (r == begin || *r != *(r - 1)) a.pairs.emplace_back(c, *r);
  }
  first_pair[n] = static_cast<int>(a.pairs.size());
  a.off.assign(a.pairs.size(), Matrix6::Zero());
  const auto off_block = [&](int col, int row) -> Matrix6& {
    int p = first_pair[col];
    while (a.pairs[p].second != row) ++p;
    return a.off[p];
  };
  for (std::size_t p = 0; p < base.pairs.size(); ++p) off_block(base.pairs[p].first, base.pairs[p].second) = base.off[p];
  for (const RankOneTerm& t : springs) {
    // On the diagonal, w's part on each block it touches.
    for (const int block : {t.block_a, t.block_b == t.block_a ? -1 : t.block_b}) {
      if (block < 0) continue;
      const Vector6 w = t.part_on(block);
      a.diagonal[block].noalias() += w * w.transpose();
    }
    if (!t.joins_two_blocks()) continue;
    // Block (row, column), row > column: w_row w_columnᵀ.
    if (t.block_a > t.block_b)
      off_block(t.block_b, t.block_a).noalias() += t.w_a * t.w_b.transpose();
    else
      off_block(t.block_a, t.block_b).noalias() += t.w_b * t.w_a.transpose();
  }
}

void multiply_with_springs(const BlockMatrix& base, const RankOneTerms& springs,
                           const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  base.multiply(x, y);
  for (const RankOneTerm& t : springs) {
    // (w wᵀ) x = w (w · x), w spread over its one or two blocks.
    double s = 0.0;
    if (t.block_a >= 0) s += t.w_a.dot(x.segment<6>(6 * t.block_a));
    if (t.block_b >= 0) s += t.w_b.dot(x.segment<6>(6 * t.block_b));
    if (t.block_a >= 0) y.segment<6>(6 * t.block_a).noalias() += s * t.w_a;
    if (t.block_b >= 0) y.segment<6>(6 * t.block_b).noalias() += s * t.w_b;
  }
}

void SpringMatrixProduct::reset(const BlockMatrix& base, const RankOneTerms& springs) {
  base_ = &base;
  springs_ = &springs;
  split_ = worth_two_threads(springs.size()) && numerics::two_threads_available();
  if (!split_) return;
  touching_.resize(static_cast<std::size_t>(numerics::thread_count()));
  const int shares = static_cast<int>(touching_.size());
  numerics::for_each_share(shares, touching_.size(), [&](int share, std::size_t, std::size_t) {
    const auto [begin, end] = numerics::share_range(share, shares, static_cast<std::size_t>(base.block_count));
    const auto inside = [&](int block) { return block >= static_cast<int>(begin) && block < static_cast<int>(end); };
    std::vector<int>& touching = touching_[share];
    touching.clear();
    for (std::size_t i = 0; i < springs.size(); ++i) {
      const RankOneTerm& t = springs[i];
      const int ends = (inside(t.block_a) ? kEndA : 0) | (inside(t.block_b) ? kEndB : 0);
      if (ends != 0) touching.push_back(static_cast<int>(i) << 2 | ends);
    }
  });
}

void SpringMatrixProduct::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  if (!split_) {
    multiply_with_springs(*base_, *springs_, x, y);
    return;
  }
  y.resize(base_->size());
  const int shares = static_cast<int>(touching_.size());
  numerics::for_each_share(shares, static_cast<std::size_t>(base_->block_count),
                           [&](int share, std::size_t begin, std::size_t end) {
    base_->multiply_rows(x, y, static_cast<int>(begin), static_cast<int>(end));
    for (const int entry : touching_[share]) {
      const RankOneTerm& t = (*springs_)[static_cast<std::size_t>(entry >> 2)];
      // As multiply_with_springs, for this share's ends of the spring only.
      double s = 0.0;
      if (t.block_a >= 0) s += t.w_a.dot(x.segment<6>(6 * t.block_a));
      if (t.block_b >= 0) s += t.w_b.dot(x.segment<6>(6 * t.block_b));
      if (entry & kEndA) y.segment<6>(6 * t.block_a).noalias() += s * t.w_a;
      if (entry & kEndB) y.segment<6>(6 * t.block_b).noalias() += s * t.w_b;
    }
  });
}

}  // namespace hydrodda::dda
