#include "coupling/pass_changes.hpp"

#include <algorithm>
#include <cmath>

namespace hydrodda::coupling {

namespace {
bool closed(dda::ContactState s) { return s != dda::ContactState::open; }
}  // namespace

int count_contact_state_changes(std::span<const dda::ContactInfo> before, std::span<const dda::ContactInfo> after) {
  // A merge of the two key-ordered lists.
  int changes = 0;
  std::size_t i = 0, j = 0;
  while (i < before.size() || j < after.size()) {
    if (j == after.size() || (i < before.size() && before[i].key < after[j].key)) {
      changes += closed(before[i++].state) ? 1 : 0;
    } else if (i == before.size() || after[j].key < before[i].key) {
      changes += closed(after[j++].state) ? 1 : 0;
    } else {
      changes += before[i++].state != after[j++].state ? 1 : 0;
    }
  }
  return changes;
}

int count_switched(std::span<const double> before, std::span<const double> after, double open_above) {
  if (before.size() != after.size()) return 0;
  int switched = 0;
  for (std::size_t c = 0; c < before.size(); ++c) switched += (before[c] > open_above) != (after[c] > open_above) ? 1 : 0;
  return switched;
}

int count_switched(std::span<const double> before, std::span<const double> after, std::span<const double> open_above) {
  if (before.size() != after.size() || after.size() != open_above.size()) return 0;
  int switched = 0;
  for (std::size_t c = 0; c < before.size(); ++c)
    switched += (before[c] > open_above[c]) != (after[c] > open_above[c]) ? 1 : 0;
  return switched;
}

double relative_load_change(const std::vector<std::vector<geometry::Point>>& current,
                            const std::vector<std::vector<geometry::Point>>& previous) {
  if (current.size() != previous.size()) return 1.0;
  double change = 0.0, largest = 0.0;
  for (std::size_t b = 0; b < current.size(); ++b) {
    if (current[b].size() != previous[b].size()) return 1.0;
    for (std::size_t v = 0; v < current[b].size(); ++v) {
      const geometry::Point f = current[b][v], g = previous[b][v];
      change = std::max(change, std::hypot(f.x - g.x, f.y - g.y));
      largest = std::max(largest, std::hypot(f.x, f.y));
    }
  }
  if (change == 0.0) return 0.0;
  return largest > 0.0 ? change / largest : 1.0;
}

}  // namespace hydrodda::coupling
