#include "fractures/tip_refinement.hpp"

#include <algorithm>
#include <cmath>

namespace hydrodda::fractures {

int current_round(const std::vector<RefinedTip>& tips) { return tips.empty() ? 1 : tips.back().round + 1; }

std::vector<RefinedTip> tips_to_refine(std::span<const WedgeTipElement> tips, int round,
                                       const std::function<double(double size)>& refine_radius) {
  std::vector<RefinedTip> added;
  if (tips.empty() || resolves_wedge_tip(tips.front())) return added;
  for (const WedgeTipElement& e : tips)
    if (!resolves_wedge_tip(e)) {
      const double size = 0.25 * e.tip.length;
      added.push_back({e.tip.point.x, e.tip.point.y, size, refine_radius(size), round});
    }
  return added;
}

std::vector<RefinedTip> merge_tips(const std::deque<PassTips>& passes) {
  std::vector<RefinedTip> merged;
  for (auto pass = passes.rbegin(); pass != passes.rend(); ++pass)
    for (const RefinedTip& t : pass->tips) {
      const auto same = std::find_if(merged.begin(), merged.end(), [&](const RefinedTip& m) {
        return std::hypot(m.x - t.x, m.y - t.y) < 4.0 * std::min(m.size, t.size);
      });
      if (same == merged.end())
        merged.push_back(t);
      else if (t.size < same->size)
        *same = {same->x, same->y, t.size, t.radius, same->round};
    }
  return merged;
}

std::vector<double> write_refined_tips(const std::vector<RefinedTip>& tips) {
  std::vector<double> numbers;
  for (const RefinedTip& t : tips)
    numbers.insert(numbers.end(), {t.x, t.y, t.size, t.radius, static_cast<double>(t.round)});
  return numbers;
}

std::vector<RefinedTip> read_refined_tips(const std::vector<double>& numbers) {
  std::vector<RefinedTip> tips;
  for (std::size_t i = 0; i + 5 <= numbers.size(); i += 5)
    tips.push_back({numbers[i], numbers[i + 1], numbers[i + 2], numbers[i + 3], static_cast<int>(numbers[i + 4])});
  return tips;
}

std::vector<double> write_recent_tips(const std::deque<PassTips>& passes) {
  std::vector<double> numbers;
  for (const PassTips& pass : passes) {
    numbers.insert(numbers.end(), {static_cast<double>(pass.iteration), static_cast<double>(pass.tips.size())});
    const std::vector<double> tips = write_refined_tips(pass.tips);
    numbers.insert(numbers.end(), tips.begin(), tips.end());
  }
  return numbers;
}

std::deque<PassTips> read_recent_tips(const std::vector<double>& numbers) {
  std::deque<PassTips> passes;
  for (std::size_t i = 0; i + 2 <= numbers.size();) {
    const auto count = static_cast<std::size_t>(numbers[i + 1]);
    const std::size_t end = i + 2 + 5 * count;
    if (end > numbers.size()) break;  // cut short: the passes read so far
    passes.push_back({static_cast<int>(numbers[i]),
                      read_refined_tips(std::vector<double>(numbers.begin() + static_cast<std::ptrdiff_t>(i + 2),
                                                            numbers.begin() + static_cast<std::ptrdiff_t>(end)))});
    i = end;
  }
  return passes;
}

}  // namespace hydrodda::fractures
