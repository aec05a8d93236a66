#pragma once
// [[geometry.tessellate]]: intact rock as bonded sub-blocks (docs/scenario.md), read and
// checked against the rest of the scenario.

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// The most sub-blocks a scenario's tessellations may make (the estimate of
// estimate_sub_blocks): about 300 bytes a contact candidate and some 20 candidates a
// sub-block, with the matrices, make some 1-2 GB of memory at this count.
inline constexpr double kMaxSubBlocks = 100'000;

// Every [[geometry.tessellate]] table of `geometry_table`, checked, into geometry.tessellations.
void read_tessellations(ReadContext& context, const TableView& geometry_table, GeometryDefinition& geometry);

// The sub-blocks a tessellation makes, roughly: six times its region's area over size² (a
// Voronoi cell has six faces on average, and either kind cuts it into a triangle on each).
double estimate_sub_blocks(const TessellationDefinition& tessellation, const Polygon& domain);

// Cross-section checks: a domain to cut, the bonds' joint type defined and without a fracture
// energy (softening bonds are not yet implemented), no flow coupled to the mechanics (broken
// bonds do not yet conduct).
void check_tessellations(ReadContext& context, const Scenario& scenario);

}  // namespace hydrodda::scenario
