#pragma once
// Which blocks a static analysis cannot hold. Static DDA resets velocities every step and seeks
// equilibrium; a group of blocks that touches nothing supported has the rigid-body motions of
// the group in the null space of its stiffness, so any load on it makes it creep without end.

#include <vector>

#include "dda/definitions.hpp"

namespace hydrodda::dda {

// The groups of blocks that touch one another (closer than `touching_distance`, the distance
// within which contacts are sought from the first step) and hold no support: no fixed block,
// fixed point, prescribed displacement or roller. Each group's blocks in increasing order, the
// groups ordered by their first block.
std::vector<std::vector<int>> find_unsupported_groups(const ModelDefinition& model, double touching_distance);

// The contact distance the system will use (System's rule: 2.5 times the allowed step
// displacement, max_displacement_ratio of half the model's height, unless set).
double initial_contact_distance(const std::vector<BlockDefinition>& blocks, const Settings& settings);

}  // namespace hydrodda::dda
