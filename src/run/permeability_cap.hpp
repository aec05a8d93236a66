#pragma once
// What a run says when the cubic law's fracture permeability reaches its cap
// (flow.fracture_permeability_cap, hydro::cubic_law_permeability): how many fluid elements,
// along which fractures, and where the first lies.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"
#include "output/run_folder.hpp"

namespace hydrodda::run {

// "the cubic law's fracture permeability w²/12 reached flow.fracture_permeability_cap =
// 8.33e-06 m² (a gap 1 cm wide) in 12 fluid elements, along fractures 3 and 7, the first at
// (1.5, 2.25): ...". `capped`: the elements, in order; `element_fractures`: per element the
// fracture whose flow zone holds it, or -1 (empty: no fracture traces). None when nothing was
// capped. Past five fractures the rest are "and N more", all of them in capped_fractures.txt in
// `folder` when one is given (output::list_items).
std::optional<std::string> describe_capped_fractures(std::span<const int> capped, const mesh::TriangleMesh& mesh,
                                                     std::span<const int> element_fractures, double cap,
                                                     const output::RunFolder* folder = nullptr);

// Of the `capped` elements, those whose permeability is the law's: an element whose permeability
// the scenario gives (`given[e]`: a material's `permeability`, a flow region's, a barrier strip's;
// run::find_fixed_permeability) takes that value, in series with its open fraction along a joint,
// and never the law's w²/12, so its cap changes no flow. Beside a roller, a fluid element whose
// open area is a round-off sliver (1e-8 of it) between bonded sub-blocks has no two facing walls
// near its centroid and a local aperture of centimetres: in a mudstone of given permeability
// that was warned about as a capped gap.
std::vector<int> capped_by_the_law(std::span<const int> capped, std::span<const std::optional<double>> given);

}  // namespace hydrodda::run
