#pragma once
// The reactions of a run's prescribed displacements: the force each `[[mechanics.displacement]]`
// exerts on the rock, summed over its points (a boundary's: one at each block vertex on it), N
// per metre of thickness. What a load frame reads: under displacement control the load, and
// past a specimen's peak its fall.

#include <string>
#include <vector>

#include "dda/system.hpp"
#include "geometry/point.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Each definition's name in history.csv: its boundary's name, or `point_<i>` for a point (i its
// place among the [[mechanics.displacement]] tables, from 1); a boundary named by two
// definitions takes `_<i>` after its name.
std::vector<std::string> reaction_names(const std::vector<scenario::PrescribedDisplacement>& displacements);

// The columns `reaction_x_<name>` and `reaction_y_<name>` of each definition, in their order.
std::vector<std::string> reaction_columns(const std::vector<scenario::PrescribedDisplacement>& displacements);

// Each definition's reaction now (the force of its springs on the blocks, summed), in the order
// of the definitions: `definitions` of them.
std::vector<geometry::Point> sum_reactions(const dda::System& system, std::size_t definitions);

// "top (0, -1.66e+06) N/m, point_2 (...) N/m": each definition's reaction now, by its name; ""
// without any.
std::string describe_reactions(const std::vector<scenario::PrescribedDisplacement>& displacements,
                               const dda::System& system);

}  // namespace hydrodda::run
