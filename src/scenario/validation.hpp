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

// The model's extent (geometry.domain and the blocks, m) and how far from the origin it may
// lie, in sizes (validation.cpp, check_model_extent, says why).
inline constexpr double kMinModelSize = 1e-3;
inline constexpr double kMaxModelSize = 1e7;
inline constexpr double kMaxOriginDistance = 1e6;

// The box of the model's domain and blocks; empty when it has neither.
geometry::Box find_model_box(const Scenario& scenario);

// A polygon the engines can use (an empty one given is refused too): at least 3 and at most
// kMaxPolygonVertices vertices, non-zero area, counter-clockwise, simple.
// True when it passed.
bool check_polygon(ReadContext& context, int line, const std::string& key, const Polygon& polygon);

// Does the segment a-b touch or cross the polygon (true when the polygon is not one, as that
// is reported where it is read)?
bool segment_meets_polygon(Point a, Point b, const Polygon& polygon);

// Do the interiors of two simple polygons share area? Touching along edges or at vertices is
// not overlap (to a relative 1e-9 of their size: coordinates in a file carry a dozen digits).
bool polygons_overlap(const Polygon& a, const Polygon& b);

// Cross-section checks, after every section has been read.
void validate_scenario(ReadContext& context, const TableView& root, Scenario& scenario);

// Every trace's joint type names a [joint.NAME]; joint apertures and barriers have traces to lie on.
void check_joint_types(ReadContext& context, const Scenario& scenario);

}  // namespace hydrodda::scenario
