#include "run/reactions.hpp"

#include <fmt/format.h>

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

std::string describe_reactions(const std::vector<scenario::PrescribedDisplacement>& displacements,
                               const dda::System& system) {
  const std::vector<std::string> names = reaction_names(displacements);
  const std::vector<geometry::Point> sums = sum_reactions(system, displacements.size());
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += fmt::format("{}{} ({:.4g}, {:.4g}) N/m", i == 0 ? "" : ", ", names[i], sums[i].x, sums[i].y);
  return text;
}

}  // namespace hydrodda::run
