// How long the blocks a static step moves freely take to come to rest on something.
//
// A static step starts each block from rest, so a block that no contact holds moves by
// F Δt²/2M a step however long it has moved (Shi 1988, §2.4; the unbalanced-force test,
// unbalanced_force.cpp): a stack of blocks falling into open joints moves step after step at
// one rate, a row landing at a time. A pass that steps on until the blocks are at rest
// (coupling's settle) can tell from those rates and the gaps ahead how long they will take:
//
//   motion_b = the largest displacement of a vertex of block b in the step; b moves when it
//              passes static_tolerance × model size
//   groups: blocks joined by closed contacts move as one; a group is at rest (T = 0) when one
//           of its blocks is fixed or does not move, and otherwise moves freely
//   for each open contact c between blocks i and j of different groups, its penetration
//   linearised as in the step (inward positive): its gap g_c = max(0, −p_c(d)), its closing in
//   the step δ_c = p_c(d) − p_c(0) = δ_c,i + δ_c,j, the parts each block's own motion makes;
//   δ_c,j > motion_j / 10: j moves onto i, and once i's group has come to rest closes what is
//                          left of the gap alone:  T_j ≤ T_i + max(0, g_c − δ_c T_i) / δ_c,j
//                          (and the same with i and j swapped)
//   T of a group: the least such steps over its blocks, found as shortest paths from the
//   groups at rest (Dijkstra)
//   free_drift    = max over the blocks of moving groups of T, where finite
//   meets nothing: a block of a moving group whose T is infinite
//
// A stack falling into open joints has every row's joint with the row under it closing by
// nothing: its lowest row lands on what holds it in g/δ steps, row k some k × g/δ steps later.
// A block moving away from the one it would follow (the rest of a column rising off a block
// that falls back) never lands behind it, nor does a block that closes only on blocks that
// themselves meet nothing. A block that meets nothing (a block jacked up off its base, a column
// lifted past the critical gradient) has no landing to foresee: the step names it, and the
// coupled loop judges whether it escapes.

#include "dda/free_drift.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "dda/block_kernels.hpp"
#include "dda/system.hpp"

namespace hydrodda::dda {

namespace {

constexpr double kNever = FreeDrift::kNever;

// A block that lands once another has: `follower` closes a gap `gap` (now) on `leader` by
// `alone` a step by its own motion, and by `both` a step while both move.
struct Follower {
  std::size_t follower;
  double gap;
  double both;
  double alone;
  // The step the follower lands, the leader having landed at `leader_lands`.
  double lands_after(double leader_lands) const {
    return leader_lands + std::max(0.0, gap - both * leader_lands) / alone;
  }
};

// Shortest paths from the blocks at rest, along the followers' gaps: each block's
// `steps` lowered to the least landing any chain of followers gives it.
void propagate_landings(const std::vector<std::vector<Follower>>& followers, std::vector<double>& steps) {
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::size_t b = 0; b < steps.size(); ++b)
    if (steps[b] < kNever) queue.push({steps[b], b});
  while (!queue.empty()) {
    const auto [t, b] = queue.top();
    queue.pop();
    if (t > steps[b]) continue;
    for (const Follower& f : followers[b]) {
      const double later = f.lands_after(t);
      if (later < steps[f.follower]) {
        steps[f.follower] = later;
        queue.push({later, f.follower});
      }
    }
  }
}

}  // namespace

void System::measure_free_drift(const Eigen::VectorXd& d, StepReport& report) {
  const std::size_t n = blocks_.size();
  std::vector<double> motion(n, 0.0);
  for (std::size_t bi = 0; bi < n; ++bi) {
    const Block& b = blocks_[bi];
    if (b.dof < 0) continue;
    const BlockMotion move(b.moments.centroid, d.segment<6>(6 * b.dof));
    for (Point p : b.polygon) motion[bi] = std::max(motion[bi], geometry::distance(p, move(p)));
  }
  // Blocks held together by closed contacts move as one: a group, named by its root.
  std::vector<std::size_t> group(n);
  for (std::size_t b = 0; b < n; ++b) group[b] = b;
  const auto root = [&](std::size_t b) {
    while (group[b] != b) b = group[b] = group[group[b]];
    return b;
  };
  for (const ActiveContact& c : active_)
    if (c.record.state != ContactState::open)
      group[root(static_cast<std::size_t>(c.key.block_i))] = root(static_cast<std::size_t>(c.key.block_j));
  // A group is at rest (lands in 0 steps) when one of its blocks is fixed or does not move.
  const double still = at_rest_displacement();
  std::vector<double> steps(n, kNever);
  for (std::size_t b = 0; b < n; ++b)
    if (blocks_[b].dof < 0 || motion[b] <= still) steps[root(b)] = 0.0;
  std::vector<std::vector<Follower>> followers(n);  // by the leader's group
  for (const ActiveContact& c : active_) {
    const auto i = static_cast<std::size_t>(c.key.block_i), j = static_cast<std::size_t>(c.key.block_j);
    const std::size_t gi = root(i), gj = root(j);
    if (c.record.state != ContactState::open || gi == gj) continue;
    const double by_i = c.en_i.dot(block_unknowns(d, c.dof_i));
    const double by_j = c.en_j.dot(block_unknowns(d, c.dof_j));
    const double closing = by_i + by_j;
    const double gap = std::max(0.0, -(c.penetration0 + closing));
    if (by_j > 0.1 * motion[j]) followers[gi].push_back({gj, gap, closing, by_j});
    if (by_i > 0.1 * motion[i]) followers[gj].push_back({gi, gap, closing, by_i});
  }
  propagate_landings(followers, steps);
  report.free_drift_steps = 0.0;
  report.free_drift_block = -1;
  report.block_meeting_nothing = -1;
  free_drift_.landing_steps.resize(n);
  for (std::size_t b = 0; b < n; ++b) {
    const double lands = steps[root(b)];
    free_drift_.landing_steps[b] = lands;
    if (!(lands < kNever)) {
      if (report.block_meeting_nothing < 0) report.block_meeting_nothing = static_cast<int>(b);
    } else if (lands > report.free_drift_steps) {
      report.free_drift_steps = lands;
      report.free_drift_block = static_cast<int>(b);
    }
  }
  free_drift_.motion = std::move(motion);
}

}  // namespace hydrodda::dda
