#include "dda/linear_solver.hpp"

#include <algorithm>

namespace hydrodda::dda {

bool find_changed_terms(const std::vector<RankOneTerm>& now, const std::vector<RankOneTerm>& before,
                        std::size_t limit, std::vector<RankOneTerm>& added,
                        std::vector<RankOneTerm>& removed) {
  added.clear();
  removed.clear();
  // One walk over both sorted lists.
  std::size_t i = 0, j = 0;
  while (i < now.size() || j < before.size()) {
    if (j == before.size() || (i < now.size() && now[i].id < before[j].id)) {
      added.push_back(now[i++]);
    } else if (i == now.size() || before[j].id < now[i].id) {
      removed.push_back(before[j++]);
    } else {
      ++i;
      ++j;
    }
    if (added.size() + removed.size() > limit) return false;
  }
  return true;
}

BlockMatrix add_springs(const BlockMatrix& base, const std::vector<RankOneTerm>& springs) {
  BlockMatrix a;
  a.block_count = base.block_count;
  a.diagonal = base.diagonal;
  a.pairs = base.pairs;
  for (const RankOneTerm& t : springs)
    if (t.block_a >= 0 && t.block_b >= 0 && t.block_a != t.block_b)
      a.pairs.emplace_back(std::min(t.block_a, t.block_b), std::max(t.block_a, t.block_b));
  std::sort(a.pairs.begin(), a.pairs.end());
  a.pairs.erase(std::unique(a.pairs.begin(), a.pairs.end()), a.pairs.end());
  a.off.assign(a.pairs.size(), Matrix6::Zero());
  const auto off_block = [&](int col, int row) -> Matrix6& {
    return a.off[std::lower_bound(a.pairs.begin(), a.pairs.end(), std::make_pair(col, row)) - a.pairs.begin()];
  };
  for (std::size_t p = 0; p < base.pairs.size(); ++p) off_block(base.pairs[p].first, base.pairs[p].second) = base.off[p];
  for (const RankOneTerm& t : springs) {
    if (t.block_a >= 0 && t.block_a == t.block_b) {
      const Eigen::Matrix<double, 6, 1> w = t.w_a + t.w_b;
      a.diagonal[t.block_a].noalias() += w * w.transpose();
      continue;
    }
    if (t.block_a >= 0) a.diagonal[t.block_a].noalias() += t.w_a * t.w_a.transpose();
    if (t.block_b >= 0) a.diagonal[t.block_b].noalias() += t.w_b * t.w_b.transpose();
    if (t.block_a < 0 || t.block_b < 0) continue;
    // Block (row, column), row > column: w_row w_columnᵀ.
    if (t.block_a > t.block_b)
      off_block(t.block_b, t.block_a).noalias() += t.w_a * t.w_b.transpose();
    else
      off_block(t.block_a, t.block_b).noalias() += t.w_b * t.w_a.transpose();
  }
  return a;
}

void multiply_with_springs(const BlockMatrix& base, const std::vector<RankOneTerm>& springs,
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

}  // namespace hydrodda::dda
