#pragma once
// Checks that need more than one key: polygons, cross-references, the sections a run needs.

#include <string>

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// A polygon the engines can use: at least 3 vertices, non-zero area, counter-clockwise, simple.
void check_polygon(ReadContext& context, int line, const std::string& key, const Polygon& polygon);

// Cross-section checks, after every section has been read.
void validate_scenario(ReadContext& context, const TableView& root, Scenario& scenario);

}  // namespace hydrodda::scenario
