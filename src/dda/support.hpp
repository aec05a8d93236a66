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

// The contact penetration tolerance the system will use (System's rule: 1e-4 of the allowed
// step displacement, unless set).
double initial_penetration_tolerance(const std::vector<BlockDefinition>& blocks, const Settings& settings);

// Settings::max_displacement_ratio for these blocks: `ratio`, or less where the blocks are thin
// against the model, so that the contact distance 2.5 r w0 (w0 half the model's height) is at
// most half the thinnest block's width (geometry::width_across_edges), r ≤ 0.2 w_min / w0.
// A contact distance beyond a block's width makes each vertex a candidate against the edges
// across its neighbours, every step, and a step of half a block's width is beyond DDA's
// first-order motion. A seal of 0.2 m beds 20 m high: 0.25 m against 0.2 m at r = 0.01, and
// 200,000 candidates for 10,200 blocks, none of which can close without crossing a block.
double displacement_ratio_for_blocks(const std::vector<BlockDefinition>& blocks, double ratio);

}  // namespace hydrodda::dda
