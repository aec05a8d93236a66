#pragma once
// Checks that need more than one key: polygons, cross-references, the sections a run needs.

#include <cstddef>
#include <string>

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// The most vertices a polygon of the scenario may have. Meshing a flow region of n vertices
// took 9.7 s at n = 1,000 and over 120 s at n = 10,000 (Gmsh's OCC fragment, which cannot be
// stopped); at 10^5 many minutes.
inline constexpr std::size_t kMaxPolygonVertices = 2'000;

// A polygon the engines can use (an empty one given is refused too): at least 3 and at most
// kMaxPolygonVertices vertices, non-zero area, counter-clockwise, simple.
void check_polygon(ReadContext& context, int line, const std::string& key, const Polygon& polygon);

// Cross-section checks, after every section has been read.
void validate_scenario(ReadContext& context, const TableView& root, Scenario& scenario);

}  // namespace hydrodda::scenario
