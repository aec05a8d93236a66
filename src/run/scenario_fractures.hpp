#pragma once
// The fractures of a scenario (fractures/ measures them): the traces its blocks were cut along,
// the meter over them, what resolves a wedge tip under its [mesh], and the [[mesh.refine]]
// points of the tips a run refines around.

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fractures/fracture_results.hpp"
#include "fractures/tip_refinement.hpp"
#include "output/run_folder.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// The layout of a scenario with a [geometry] domain (the same cut the model's blocks come
// from: the cut is deterministic); none for a scenario that lists its blocks.
std::optional<fractures::FractureLayout> fracture_layout(const scenario::Scenario& scenario);

// The meter of a scenario with a [geometry] domain, nodes at most 1/50 of the domain's larger
// side apart; none for a scenario that lists its blocks.
std::optional<fractures::FractureMeter> make_fracture_meter(const scenario::Scenario& scenario);

// A message when the element at the first of `tips` (find_wedge_tip_elements) is more than s*/2
// across: naming the fracture, its tip, α, s* and the element's size, and what resolves it under
// `mesh` (the scenario's [mesh]): where the tip lies on its trace (within mesh.fracture_size), a
// smaller mesh.fracture_size; else refinement around the tips, a [[mesh.refine]] table for each
// unresolved one, or mesh.refine_tips (unless it is on); in a mesh file, a refinement of the
// file. None when every tip is resolved. Past a few tables the rest are in `folder`'s
// unresolved_tips.toml, which the message names (output::list_items).
std::optional<std::string> describe_unresolved_wedge_tips(std::span<const fractures::WedgeTipElement> tips,
                                                          const scenario::MeshDefinition& mesh,
                                                          const output::RunFolder* folder = nullptr);

// The [[mesh.refine]] points of refined tips.
std::vector<scenario::MeshRefinePoint> refine_points(const std::vector<fractures::RefinedTip>& tips);

// mesh.refine's default radius for a refinement of `size` in the scenario's `mesh` (for
// fractures::tips_to_refine).
std::function<double(double size)> default_refine_radius(const scenario::MeshDefinition& mesh);

}  // namespace hydrodda::run
