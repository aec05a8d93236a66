#include "breach/pass_trail.hpp"

#include <algorithm>
#include <utility>

namespace hydrodda::breach {

void PassTrail::add(bool at_rest, bool full_time_step, bool moved, std::vector<std::optional<double>> conductivity) {
  passes_.push_back({at_rest, full_time_step, moved, std::move(conductivity)});
}

int PassTrail::passes_not_at_rest() const {
  int moving = 0;
  for (auto p = passes_.rbegin(); p != passes_.rend() && !p->at_rest; ++p) ++moving;
  return moving;
}

bool PassTrail::getting_through() const {
  if (passes_.empty()) return false;
  const Pass& last = passes_.back();
  return !last.at_rest && !last.full_time_step && last.moved;
}

bool PassTrail::rested_in_last(int n) const {
  const int count = std::min(n, passes());
  if (count <= 0) return false;
  return std::all_of(passes_.end() - count, passes_.end(), [](const Pass& p) { return p.at_rest && p.full_time_step; });
}

int PassTrail::passes_cut_short(int n) const {
  const int count = std::max(std::min(n, passes()), 0);
  return static_cast<int>(
      std::count_if(passes_.end() - count, passes_.end(), [](const Pass& p) { return !p.full_time_step; }));
}

std::vector<std::optional<ValueRange>> PassTrail::ranges_over_last(int n) const {
  const int count = std::min(n, passes());
  std::vector<std::optional<ValueRange>> ranges;
  for (auto p = passes_.end() - std::max(count, 0); p != passes_.end(); ++p) {
    if (ranges.size() < p->conductivity.size()) ranges.resize(p->conductivity.size());
    for (std::size_t r = 0; r < p->conductivity.size(); ++r) {
      if (!p->conductivity[r]) continue;
      const double k = *p->conductivity[r];
      if (!ranges[r]) ranges[r] = ValueRange{k, k};
      ranges[r]->least = std::min(ranges[r]->least, k);
      ranges[r]->largest = std::max(ranges[r]->largest, k);
    }
  }
  return ranges;
}

}  // namespace hydrodda::breach
