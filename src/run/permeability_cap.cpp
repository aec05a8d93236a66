#include "run/permeability_cap.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <vector>

#include "output/item_list.hpp"

namespace hydrodda::run {

std::optional<std::string> describe_capped_fractures(std::span<const int> capped, const mesh::TriangleMesh& mesh,
                                                     std::span<const int> element_fractures, double cap,
                                                     const output::RunFolder* folder) {
  if (capped.empty()) return std::nullopt;
  std::set<int> fractures;
  for (int e : capped)
    if (static_cast<std::size_t>(e) < element_fractures.size() && element_fractures[e] >= 0)
      fractures.insert(element_fractures[e]);
  std::string along;
  if (!fractures.empty()) {
    std::vector<std::string> ids;
    for (int f : fractures) ids.push_back(std::to_string(f));
    along = fmt::format(", along fracture{} {}", fractures.size() == 1 ? "" : "s",
                        output::list_items(ids, folder, "capped_fractures.txt"));
  }
  const geometry::Point first = mesh::triangle_centroid(mesh, capped.front());
  return fmt::format(
      "the cubic law's fracture permeability w²/12 reached flow.fracture_permeability_cap = {:.4g} m² (a gap {:.3g} mm "
      "wide) in {} fluid element{}{}, the first at ({:.4g}, {:.4g}): their flow is the cap's, less than the cubic "
      "law's for gaps that wide (docs/coupling.md, \"The fracture permeability cap\")",
      cap, 1e3 * std::sqrt(12.0 * cap), capped.size(), capped.size() == 1 ? "" : "s", along, first.x, first.y);
}

std::vector<int> capped_by_the_law(std::span<const int> capped, std::span<const std::optional<double>> given) {
  std::vector<int> kept;
  for (int e : capped)
    if (static_cast<std::size_t>(e) >= given.size() || !given[static_cast<std::size_t>(e)]) kept.push_back(e);
  return kept;
}

}  // namespace hydrodda::run
