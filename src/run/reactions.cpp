#include "run/reactions.hpp"

#include <algorithm>
#include <string>

namespace hydrodda::run {

std::vector<std::string> reaction_names(const std::vector<scenario::PrescribedDisplacement>& displacements) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < displacements.size(); ++i) {
    const std::string& boundary = displacements[i].boundary;
    const std::string place = std::to_string(i + 1);
    if (boundary.empty()) {
      names.push_back("point_" + place);
      continue;
    }
    const auto same = [&boundary](const scenario::PrescribedDisplacement& d) { return d.boundary == boundary; };
    const bool shared = std::count_if(displacements.begin(), displacements.end(), same) > 1;
    names.push_back(shared ? boundary + "_" + place : boundary);
  }
  return names;
}

std::vector<std::string> reaction_columns(const std::vector<scenario::PrescribedDisplacement>& displacements) {
  std::vector<std::string> columns;
  for (const std::string& name : reaction_names(displacements)) {
    columns.push_back("reaction_x_" + name);
    columns.push_back("reaction_y_" + name);
  }
  return columns;
}

std::vector<geometry::Point> sum_reactions(const dda::System& system, std::size_t definitions) {
  std::vector<geometry::Point> sums(definitions);
  for (const dda::System::PrescribedProgress& p : system.prescribed_progress())
    sums.at(static_cast<std::size_t>(p.entry)) += p.reaction;
  return sums;
}

}  // namespace hydrodda::run
