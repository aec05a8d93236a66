#include "scenario/load_times.hpp"

#include <algorithm>

namespace hydrodda::scenario {

std::vector<double> find_load_times(const Scenario& s) {
  std::vector<double> times;
  const auto add = [&](const numerics::TimeTable& table) {
    if (!table.is_constant()) times.insert(times.end(), table.times().begin(), table.times().end());
  };
  if (s.flow)
    for (const FlowBoundaryCondition& bc : s.flow->boundaries) add(bc.value);
  if (s.mechanics) {
    for (const Traction& t : s.mechanics->tractions)
      for (const numerics::TimeTable* table : {&t.normal, &t.normal_end, &t.shear, &t.shear_end}) add(*table);
    for (const PointLoad& l : s.mechanics->loads) add(l.force);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

double find_final_load_time(const Scenario& s) {
  const std::vector<double> times = find_load_times(s);
  return times.empty() ? 0.0 : times.back();
}

}  // namespace hydrodda::scenario
