// Gmsh meshing of a MeshRequest: coverage, boundary names, regions honoured, refinement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <omp.h>

#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {
namespace {

double total_area(const TriangleMesh& m) {
  double a = 0.0;
  for (int t = 0; t < m.triangle_count(); ++t) a += triangle_area(m, t);
  return a;
}

std::map<std::string, double> boundary_lengths(const TriangleMesh& m) {
  std::map<std::string, double> length;
  for (const BoundaryEdge& e : m.boundary_edges)
    length[e.boundary < 0 ? "(unnamed)" : m.boundary_names[e.boundary]] +=
        geometry::distance(m.nodes[e.nodes[0]], m.nodes[e.nodes[1]]);
  return length;
}

// Gmsh sets the process's OpenMP thread count to its own option (omp_set_num_threads):
// meshing gives the program's back, or every parallel part after it would run on one thread.
TEST(GenerateMesh, MeshingLeavesTheProgramsThreadCountAsItWas) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(3);
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.1;
  const TriangleMesh m = generate_mesh(request);
  EXPECT_GT(m.triangle_count(), 0);
  EXPECT_EQ(omp_get_max_threads(), 3);
  omp_set_num_threads(before);
}

// An L-shaped domain, clockwise on input: the mesh covers its area exactly (1e-12), is
// counter-clockwise, and the default sides name only where the boundary lies on the box:
// left and bottom are whole (2 m), right and top are the 1 m stubs; the two inner edges
// (x = 1 from y = 1 to 2, y = 1 from x = 1 to 2) are unnamed (2 m).
TEST(GenerateMesh, LShapeWithDefaultBoundaries) {
  MeshRequest request;
  request.domain = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  request.size = 0.1;
  const TriangleMesh m = generate_mesh(request);
  validate(m);
  EXPECT_NEAR(total_area(m), 3.0, 1e-12);
  const auto length = boundary_lengths(m);
  EXPECT_NEAR(length.at("left"), 2.0, 1e-12);
  EXPECT_NEAR(length.at("bottom"), 2.0, 1e-12);
  EXPECT_NEAR(length.at("right"), 1.0, 1e-12);
  EXPECT_NEAR(length.at("top"), 1.0, 1e-12);
  EXPECT_NEAR(length.at("(unnamed)"), 2.0, 1e-12);
  // Size 0.1 on 3 m²: an equilateral triangle of side 0.1 has area 0.0043, so ~700 triangles.
  EXPECT_GT(m.triangle_count(), 400);
  EXPECT_LT(m.triangle_count(), 1400);
}

// A named segment in the middle of the bottom side: its ends become mesh nodes, it takes
// precedence over "bottom", and the rest of the bottom stays "bottom".
TEST(GenerateMesh, NamedSegmentSplitsADefaultSide) {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.07;
  request.boundaries = {{"inlet", {0.33, 0.0}, {0.61, 0.0}}};
  const TriangleMesh m = generate_mesh(request);
  const auto length = boundary_lengths(m);
  EXPECT_NEAR(length.at("inlet"), 0.28, 1e-12);
  EXPECT_NEAR(length.at("bottom"), 0.72, 1e-12);
  EXPECT_EQ(m.boundary_names.front(), "inlet");
}

// Region polygons are honoured: the triangles tagged with a region cover its polygon's
// area exactly (1e-12), including a region that sticks out of the domain (clipped to it);
// a later region takes precedence where two overlap.
TEST(GenerateMesh, RegionsAreHonoured) {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.05;
  request.regions = {{"core", {{0.2, 0.1}, {0.7, 0.15}, {0.65, 0.8}, {0.25, 0.7}}},
                     {"edge", {{0.9, 0.5}, {1.5, 0.5}, {1.5, 0.7}, {0.9, 0.7}}},
                     {"spot", {{0.3, 0.3}, {0.4, 0.3}, {0.4, 0.4}, {0.3, 0.4}}}};
  const TriangleMesh m = generate_mesh(request);
  std::map<std::string, double> area;
  for (int t = 0; t < m.triangle_count(); ++t) area[m.region_names[m.region[t]]] += triangle_area(m, t);
  const double core = geometry::area(request.regions[0].polygon);
  EXPECT_NEAR(area.at("core"), core - 0.01, 1e-12);  // "spot" (0.01 m²) lies inside "core"
  EXPECT_NEAR(area.at("edge"), 0.1 * 0.2, 1e-12);
  EXPECT_NEAR(area.at("spot"), 0.01, 1e-12);
  EXPECT_NEAR(area.at("domain") + area.at("core") + area.at("edge") + area.at("spot"), 1.0, 1e-12);
}

// Refinement: triangles whose centroid is within 0.005 of the line have a mean longest edge
// within [0.75, 1.5] × the fracture size and none beyond 2.5× (Gmsh's sizes are targets, and
// a triangle there reaches up to 0.01 from the line, where the target is already 0.0097),
// and far triangles are an order of magnitude larger.
TEST(GenerateMesh, RefinesAlongLines) {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.1;
  request.fracture_size = 0.005;
  request.refine_distance = 0.2;
  request.refinement_lines = {{{0.1, 0.2}, {0.9, 0.7}}};
  const TriangleMesh m = generate_mesh(request);
  double near_max = 0.0, near_sum = 0.0, far_sum = 0.0;
  int near_count = 0, far_count = 0;
  for (int t = 0; t < m.triangle_count(); ++t) {
    const auto& tri = m.triangles[t];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, geometry::distance(m.nodes[tri[k]], m.nodes[tri[(k + 1) % 3]]));
    const double d = geometry::distance_to_segment(triangle_centroid(m, t), {0.1, 0.2}, {0.9, 0.7});
    if (d < 0.005) near_max = std::max(near_max, longest), near_sum += longest, ++near_count;
    if (d > 0.25) far_sum += longest, ++far_count;
  }
  ASSERT_GT(near_count, 0);
  EXPECT_LE(near_max, 2.5 * 0.005);
  EXPECT_GE(near_sum / near_count, 0.75 * 0.005);
  EXPECT_LE(near_sum / near_count, 1.5 * 0.005);
  ASSERT_GT(far_count, 0);
  EXPECT_GT(far_sum / far_count, 0.05);
}

TEST(GenerateMesh, RefinedSizeIsTheThresholdRamp) {
  MeshRequest r;
  r.size = 0.1, r.fracture_size = 0.01, r.refine_distance = 0.2;
  EXPECT_DOUBLE_EQ(refined_size(r, 0.0), 0.01);
  EXPECT_DOUBLE_EQ(refined_size(r, 0.1), 0.055);
  EXPECT_DOUBLE_EQ(refined_size(r, 0.2), 0.1);
  EXPECT_DOUBLE_EQ(refined_size(r, 5.0), 0.1);
}

// A refinement point ([[mesh.refine]]) with the reader's default growth, a fifth of the
// distance: the triangles whose centroid is within 0.002 of it have a longest edge within
// [0.5, 2] × its size (0.002; Gmsh's sizes are targets, and a triangle's corners lie where the
// size has grown), and the size it asks for is s + d (size − s) / radius at distance d, the
// least of the point's and the lines' where both refine.
TEST(GenerateMesh, RefinesAroundPoints) {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.1;
  request.refine_distance = 0.2;
  request.refinement_points = {{{0.3, 0.4}, 0.002, (0.1 - 0.002) / 0.2}};
  const TriangleMesh m = generate_mesh(request);
  int near_count = 0;
  double far_shortest = 1.0;
  for (int t = 0; t < m.triangle_count(); ++t) {
    const auto& tri = m.triangles[t];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, geometry::distance(m.nodes[tri[k]], m.nodes[tri[(k + 1) % 3]]));
    const double d = geometry::distance(triangle_centroid(m, t), {0.3, 0.4});
    if (d < 0.002) {
      ++near_count;
      EXPECT_LE(longest, 2.0 * 0.002) << d;
      EXPECT_GE(longest, 0.5 * 0.002) << d;
    }
    if (d > 0.6) far_shortest = std::min(far_shortest, longest);
  }
  EXPECT_GT(near_count, 3);
  EXPECT_GT(far_shortest, 0.05);  // beyond the radius, at its size
  EXPECT_DOUBLE_EQ(refined_size(request, INFINITY, {0.3, 0.4}), 0.002);
  EXPECT_NEAR(refined_size(request, INFINITY, {0.4, 0.4}), 0.002 + 0.2 * 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(refined_size(request, INFINITY, {0.3, 1.0}), 0.1);
  request.fracture_size = 0.01;
  request.refinement_lines = {{{0.0, 0.5}, {1.0, 0.5}}};
  EXPECT_DOUBLE_EQ(refined_size(request, 0.0, {0.3, 0.5}), 0.01);     // the line is finer there
  EXPECT_DOUBLE_EQ(refined_size(request, 0.1, {0.3, 0.4}), 0.002);    // the point is finer there
}

TEST(GenerateMesh, RejectsBadInput) {
  MeshRequest r;
  r.domain = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // a bow tie
  EXPECT_THROW(generate_mesh(r), std::runtime_error);
  r.domain = {{0, 0}, {1, 0}, {1, 1}};
  r.size = 0.0;
  EXPECT_THROW(generate_mesh(r), std::runtime_error);
}

// Two meshes of the same request are identical (Gmsh runs on one thread).
TEST(GenerateMesh, IsDeterministic) {
  MeshRequest r;
  r.domain = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  r.size = 0.08;
  r.refinement_lines = {{{0.2, 0.5}, {1.8, 0.6}}};
  r.fracture_size = 0.01;
  const TriangleMesh a = generate_mesh(r), b = generate_mesh(r);
  EXPECT_EQ(a.triangles, b.triangles);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) EXPECT_EQ(a.nodes[i], b.nodes[i]);
}

// The unit square graded along a refinement line, with a region, cut into about 48 tiles
// (tile_triangles 400 on a request of about 19,000 triangles).
MeshRequest tiled_request() {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.01;
  request.fracture_size = 0.004;
  request.refine_distance = 0.05;
  request.refinement_lines = {{{0.1, 0.2}, {0.9, 0.7}}};
  request.regions = {{"core", {{0.2, 0.1}, {0.7, 0.15}, {0.65, 0.8}, {0.25, 0.7}}}};
  request.tile_triangles = 400;
  return request;
}

// How far the nodes of two meshes with as many nodes lie apart, at most; infinite when their
// counts differ.
double largest_node_shift(const TriangleMesh& a, const TriangleMesh& b) {
  if (a.nodes.size() != b.nodes.size()) return std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) largest = std::max(largest, geometry::distance(a.nodes[i], b.nodes[i]));
  return largest;
}

// A mesh cut into tiles (tile_triangles 400 on a request of about 19,000 triangles: about 48
// tiles) honours what the one-surface mesh honours: regions to 1e-12 of their area, the size
// field along a refinement line (triangles within 0.005 of it: mean longest edge within
// [0.75, 1.5] × fracture_size, as RefinesAlongLines), the default boundary names (1 m each);
// it is the same mesh on every call, and has within 3% of the triangles of the one-surface
// mesh of the same request (the tile edges only add nodes on them). The tiles are meshed by
// two processes at once (the default), by one or by three: each mesh is the same on every call
// and conforms across the tiles, and all are the same mesh, node for node (the tiles are meshed
// in groups fixed by the tiles alone, whatever the number of processes).
TEST(GenerateMesh, TiledMeshHonoursRegionsSizesAndBoundaries) {
  MeshRequest request = tiled_request();
  const TriangleMesh tiled = generate_mesh(request), again = generate_mesh(request);
  EXPECT_EQ(tiled.triangles, again.triangles);
  EXPECT_EQ(tiled.nodes.size(), again.nodes.size());

  std::map<std::string, double> area;
  double near_sum = 0.0;
  int near_count = 0;
  for (int t = 0; t < tiled.triangle_count(); ++t) {
    area[tiled.region_names[tiled.region[t]]] += triangle_area(tiled, t);
    const auto& tri = tiled.triangles[t];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, geometry::distance(tiled.nodes[tri[k]], tiled.nodes[tri[(k + 1) % 3]]));
    if (geometry::distance_to_segment(triangle_centroid(tiled, t), {0.1, 0.2}, {0.9, 0.7}) < 0.005)
      near_sum += longest, ++near_count;
  }
  EXPECT_NEAR(area.at("core"), geometry::area(request.regions[0].polygon), 1e-12);
  EXPECT_NEAR(area.at("domain") + area.at("core"), 1.0, 1e-12);
  ASSERT_GT(near_count, 0);
  EXPECT_GE(near_sum / near_count, 0.75 * 0.004);
  EXPECT_LE(near_sum / near_count, 1.5 * 0.004);
  for (const auto& [name, length] : boundary_lengths(tiled)) EXPECT_NEAR(length, 1.0, 1e-12) << name;

  // The tiles meshed one process at a time instead of two: as reproducible, as conforming (a
  // crack between tiles would leave unnamed boundary edges), and the same mesh; and three.
  ASSERT_EQ(request.processes, 2);
  request.processes = 1;
  const TriangleMesh one = generate_mesh(request), one_again = generate_mesh(request);
  EXPECT_EQ(one.triangles, one_again.triangles);
  for (const auto& [name, length] : boundary_lengths(one)) EXPECT_NEAR(length, 1.0, 1e-12) << name;
  EXPECT_NEAR(one.triangle_count(), tiled.triangle_count(), 0.01 * tiled.triangle_count());
  EXPECT_EQ(one.triangles, tiled.triangles);
  EXPECT_EQ(largest_node_shift(one, tiled), 0.0);
  request.processes = 3;
  const TriangleMesh three = generate_mesh(request);
  EXPECT_EQ(three.triangles, tiled.triangles);
  EXPECT_EQ(largest_node_shift(three, tiled), 0.0);
  request.processes = 2;

  request.tile_triangles = 0;
  const TriangleMesh whole = generate_mesh(request);
  EXPECT_NEAR(tiled.triangle_count(), whole.triangle_count(), 0.03 * whole.triangle_count());
}

// The smallest angle of a triangle, in degrees.
double smallest_angle(const TriangleMesh& m, int t) {
  const auto& tri = m.triangles[t];
  double smallest = 180.0;
  for (int k = 0; k < 3; ++k) {
    const Point a = m.nodes[tri[k]], b = m.nodes[tri[(k + 1) % 3]], c = m.nodes[tri[(k + 2) % 3]];
    const Point u = b - a, v = c - a;
    smallest = std::min(smallest, std::atan2(std::abs(geometry::cross(u, v)), geometry::dot(u, v)) * 180.0 / M_PI);
  }
  return smallest;
}

struct AngleCounts {
  int below_20 = 0, below_30 = 0;
  double mean = 0.0;  // of the triangles' smallest angles
};
AngleCounts count_angles(const TriangleMesh& m) {
  AngleCounts counts;
  for (int t = 0; t < m.triangle_count(); ++t) {
    const double a = smallest_angle(m, t);
    counts.below_20 += a < 20.0 ? 1 : 0;
    counts.below_30 += a < 30.0 ? 1 : 0;
    counts.mean += a / m.triangle_count();
  }
  return counts;
}

// A tiled mesh is not smoothed unless asked (MeshRequest::smoothing): Gmsh's Delaunay
// refinement alone shapes the triangles well, graded along a refinement line and cut by a
// region and by the tiles' edges: no more triangles below 20° than the smoothed mesh, a few
// per thousand below 30°, a mean smallest angle above 45°. One pass asked for moves the nodes
// (as many of them); a mesh of one surface keeps its pass unless asked.
TEST(GenerateMesh, TiledMeshIsWellShapedWithoutSmoothing) {
  MeshRequest request = tiled_request();
  ASSERT_EQ(request.smoothing, -1);
  const TriangleMesh chosen = generate_mesh(request);
  request.smoothing = 0;
  const TriangleMesh unsmoothed = generate_mesh(request);
  request.smoothing = 1;
  const TriangleMesh smoothed = generate_mesh(request);
  EXPECT_EQ(chosen.triangles, unsmoothed.triangles);
  EXPECT_EQ(largest_node_shift(chosen, unsmoothed), 0.0);
  ASSERT_EQ(smoothed.nodes.size(), unsmoothed.nodes.size());
  EXPECT_GT(largest_node_shift(smoothed, unsmoothed), 1e-4) << "smoothing = 1 moved no node";

  // Below 20° lie only the triangles the input forces: where the refinement line and the
  // region's sides cross the tiles' edges at small angles, nodes no smoothing moves (48 of
  // 31,016 in both meshes).
  const AngleCounts plain = count_angles(unsmoothed), moved_nodes = count_angles(smoothed);
  EXPECT_LE(plain.below_20, moved_nodes.below_20);
  EXPECT_LT(plain.below_20, 0.002 * unsmoothed.triangle_count());
  EXPECT_LT(plain.below_30, 0.005 * unsmoothed.triangle_count());  // 99 (smoothed: 81)
  EXPECT_GT(plain.mean, 45.0);                                     // 46.5° (smoothed: 48.5°)

  // The same request as one surface (every shipped scenario's mesh) keeps its one pass.
  request.tile_triangles = 0;
  request.smoothing = -1;
  const TriangleMesh whole = generate_mesh(request);
  request.smoothing = 1;
  const TriangleMesh whole_smoothed = generate_mesh(request);
  EXPECT_EQ(whole.triangles, whole_smoothed.triangles);
  EXPECT_EQ(largest_node_shift(whole, whole_smoothed), 0.0);
}

}  // namespace
}  // namespace hydrodda::mesh

namespace hydrodda::mesh {
namespace {

// A user segment named "left" replaces the default left side: only its 0.4 m are "left",
// the rest of that side is unnamed, and the name appears once. Two segments may share a name.
TEST(GenerateMesh, UserSegmentReplacesDefaultSide) {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.05;
  request.boundaries = {{"left", {0, 0.2}, {0, 0.6}}, {"vents", {1, 0}, {1, 0.1}}, {"vents", {1, 0.9}, {1, 1}}};
  const TriangleMesh m = generate_mesh(request);
  EXPECT_EQ(std::count(m.boundary_names.begin(), m.boundary_names.end(), "left"), 1);
  const auto length = boundary_lengths(m);
  EXPECT_NEAR(length.at("left"), 0.4, 1e-12);
  EXPECT_NEAR(length.at("vents"), 0.2, 1e-12);
  EXPECT_NEAR(length.at("right"), 0.8, 1e-12);
  EXPECT_NEAR(length.at("(unnamed)"), 0.6, 1e-12);
}

// Flow-only scenarios give a region covering the whole domain, then regions inside it: the
// whole-domain region gets what the later ones leave (areas exact to 1e-12).
TEST(GenerateMesh, RegionCoveringTheDomainThenStrips) {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.05;
  request.regions = {{"matrix", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
                     {"f1", {{0, 0.248}, {1, 0.248}, {1, 0.252}, {0, 0.252}}}};
  const TriangleMesh m = generate_mesh(request);
  std::map<std::string, double> area;
  for (int t = 0; t < m.triangle_count(); ++t) area[m.region_names[m.region[t]]] += triangle_area(m, t);
  EXPECT_EQ(area.count("domain"), 0u);
  EXPECT_NEAR(area.at("matrix"), 1.0 - 0.004, 1e-12);
  EXPECT_NEAR(area.at("f1"), 0.004, 1e-12);
}

}  // namespace
}  // namespace hydrodda::mesh
