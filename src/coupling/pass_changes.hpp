#pragma once
// What changed across one coupling pass, as plain counts (PassReport's contact_state_changes,
// joint_crossings_switched and fluid_load_change): where a loop that does not settle has its
// contacts chattering, its joints switching between open and closed, or its fluid load still
// moving.

#include <span>
#include <vector>

#include "dda/system.hpp"
#include "geometry/point.hpp"

namespace hydrodda::coupling {

// Contacts whose state differs between `before` and `after` (each in key order, as
// dda::System::contacts gives them); a contact in only one of them counts when it is closed
// (locked or sliding) there: an open contact that appears or goes changes nothing.
int count_contact_state_changes(std::span<const dda::ContactInfo> before, std::span<const dda::ContactInfo> after);

// Positions where one aperture is above `open_above` and the other not (the joint crossings
// open at one end of a pass and closed at the other); 0 when the sizes differ (no pass before).
int count_switched(std::span<const double> before, std::span<const double> after, double open_above);
// The same with each position's own threshold (joint crossings of types with their own laws).
int count_switched(std::span<const double> before, std::span<const double> after, std::span<const double> open_above);

// max over blocks and vertices |f − f'| / max |f| (0 when f is zero everywhere and unchanged,
// 1 when f' is empty or of other sizes: no pass before).
double relative_load_change(const std::vector<std::vector<geometry::Point>>& current,
                            const std::vector<std::vector<geometry::Point>>& previous);

}  // namespace hydrodda::coupling
