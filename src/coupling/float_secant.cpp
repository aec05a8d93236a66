#include "coupling/float_secant.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <set>
#include <stdexcept>

namespace hydrodda::coupling {

std::vector<std::vector<int>> find_free_groups(std::span<const double> landing_steps,
                                               std::span<const dda::ContactInfo> contacts) {
  const std::size_t n = landing_steps.size();
  const auto free = [&](int b) { return b >= 0 && static_cast<std::size_t>(b) < n && std::isinf(landing_steps[b]); };
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t b) {
    while (parent[b] != b) b = parent[b] = parent[parent[b]];
    return b;
  };
  // Closed or open: blocks near enough to be in contact move as one, so that no gap among
  // them changes.
  for (const dda::ContactInfo& c : contacts)
    if (free(c.key.block_i) && free(c.key.block_j))
      parent[root(static_cast<std::size_t>(c.key.block_i))] = root(static_cast<std::size_t>(c.key.block_j));
  std::map<std::size_t, std::vector<int>> groups;
  for (std::size_t b = 0; b < n; ++b)
    if (free(static_cast<int>(b))) groups[root(b)].push_back(static_cast<int>(b));
  std::vector<std::vector<int>> result;
  for (auto& [r, blocks] : groups) result.push_back(std::move(blocks));
  return result;
}

Point FloatSecant::shift(const std::vector<int>& group, Point start, Point end, double least_advance,
                         double sum_squared_steps, double largest_shift) {
  if (!(sum_squared_steps > 0.0)) return {0.0, 0.0};
  const Point motion = end - start;
  const Point rate{motion.x / sum_squared_steps, motion.y / sum_squared_steps};
  const auto it = last_.find(group);
  const bool paired = it != last_.end();
  const Memory before = paired ? it->second : Memory{};
  last_[group] = {start, rate};
  const Point s = start - before.start;
  const Point y = rate - before.rate;
  const double ss = geometry::dot(s, s);
  if (!(ss > 0.0)) return {0.0, 0.0};
  const double kappa = -geometry::dot(y, s) / ss;
  // The pass itself closes κ Σ Δt² of the distance to the secant's float: under a thousandth
  // it lies a thousand passes' motion ahead or more, and its κ is as likely round-off.
  if (!(kappa * sum_squared_steps >= kLeastClosing)) return {0.0, 0.0};
  const Point target{start.x + rate.x / kappa, start.y + rate.y / kappa};
  Point shift = target - end;
  double scale = 1.0;
  const double moved = std::sqrt(geometry::dot(motion, motion));
  if (moved > 0.0) {
    const double back = -geometry::dot(shift, motion) / moved;  // how far it goes back along its motion
    if (back > 0.0) scale = std::min(scale, std::max(0.0, least_advance) / back);
  }
  const double length = std::sqrt(geometry::dot(shift, shift));
  if (length * scale > largest_shift) scale = std::min(scale, largest_shift / length);
  return {shift.x * scale, shift.y * scale};
}

void FloatSecant::keep_only(const std::vector<std::vector<int>>& free_now) {
  // A set, not a scan of the list per remembered group: a seal's free blocks may be thousands
  // of groups.
  const std::set<std::vector<int>> free(free_now.begin(), free_now.end());
  std::erase_if(last_, [&](const auto& entry) { return !free.contains(entry.first); });
}

std::vector<FloatSecant::Remembered> FloatSecant::remembered() const {
  std::vector<Remembered> memory;
  for (const auto& [group, m] : last_) memory.push_back({group, m.start, m.rate});
  return memory;
}

void FloatSecant::restore(const std::vector<Remembered>& memory, int block_count) {
  std::map<std::vector<int>, Memory> last;
  for (const Remembered& r : memory) {
    const bool ascending = std::adjacent_find(r.group.begin(), r.group.end(), std::greater_equal<>()) == r.group.end();
    const bool known = !r.group.empty() && r.group.front() >= 0 && r.group.back() < block_count;
    if (!ascending || !known || !last.emplace(r.group, Memory{r.start, r.rate}).second)
      throw std::invalid_argument("float secant: a remembered group that is not a list of this system's blocks");
  }
  last_ = std::move(last);
}

}  // namespace hydrodda::coupling
