#pragma once
// Materials by region ([material.NAME] region): which blocks and fluid elements take which
// material (scenario_queries.hpp), and the checks that make that choice unambiguous.

#include "scenario/scenario_queries.hpp"
#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// The checks on reading: regions only with a cut domain (blocks given one by one name their
// material), each meeting the domain, no two overlapping, at most one material without one.
void check_material_regions(ReadContext& context, const TableView& root, const Scenario& scenario);

}  // namespace hydrodda::scenario
