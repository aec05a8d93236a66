#include "dda/linear_solver.hpp"

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

}  // namespace hydrodda::dda
