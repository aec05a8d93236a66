#include "geometry/block_network.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/joint_sets.hpp"
#include "geometry/portable_random.hpp"

namespace hydrodda::geometry {
namespace {

const Polygon kSquare{{0, 0}, {4, 0}, {4, 4}, {0, 4}};

double total_area(const std::vector<Polygon>& blocks) {
  double a = 0.0;
  for (const Polygon& b : blocks) a += signed_area(b);
  return a;
}

std::vector<FractureTrace> listed(const std::vector<Segment2>& segments) {
  std::vector<FractureTrace> traces;
  for (std::size_t i = 0; i < segments.size(); ++i)
    traces.push_back({segments[i], {TraceSource::listed, -1, static_cast<int>(i)}});
  return traces;
}

bool on_domain_boundary(Point p, const Polygon& domain, double tolerance) {
  for (std::size_t i = 0; i < domain.size(); ++i)
    if (distance_to_segment(p, domain[i], domain[(i + 1) % domain.size()]) <= tolerance) return true;
  return false;
}

TEST(BlockNetwork, EachEdgeKnowsItsFracture) {
  const BlockNetwork net = build_block_network({kSquare, listed({{{2, 0}, {2, 4}}, {{0, 1}, {4, 1}}}), {}, 0.0, 0.0});
  ASSERT_EQ(net.blocks.size(), 4u);
  for (std::size_t b = 0; b < net.blocks.size(); ++b) {
    const Polygon& p = net.blocks[b];
    ASSERT_EQ(net.edge_fractures[b].size(), p.size());
    for (std::size_t e = 0; e < p.size(); ++e) {
      const Point a = p[e], c = p[(e + 1) % p.size()];
      const int f = net.edge_fractures[b][e];
      if (f < 0) {
        EXPECT_TRUE(on_domain_boundary(0.5 * (a + c), kSquare, 1e-12));
      } else {
        EXPECT_EQ(a.x == 2 && c.x == 2, f == 0);
        EXPECT_EQ(a.y == 1 && c.y == 1, f == 1);
      }
    }
  }
  EXPECT_EQ(net.merged_small, 0);
  // The faces: the vertical trace in two pieces, the horizontal one in two, each listed once.
  ASSERT_EQ(net.faces.size(), 4u);
  double length[2] = {0, 0};
  for (const FractureFace& f : net.faces) length[f.fracture] += distance(f.segment.from, f.segment.to);
  EXPECT_NEAR(length[0], 4.0, 1e-15);
  EXPECT_NEAR(length[1], 4.0, 1e-15);
}

TEST(BlockNetwork, AnIslandOfTracesIsDroppedNotLeftAsAHole) {
  // Four short traces crossing into a closed square in the middle of the domain, touching
  // nothing else: the middle square would be a block inside another, which has a hole. Like
  // traces that do not cut a block through, they are dropped: one block.
  const auto traces = listed({{{1.4, 1.5}, {2.6, 1.5}}, {{2.5, 1.4}, {2.5, 2.6}}, {{2.6, 2.5}, {1.4, 2.5}}, {{1.5, 2.6}, {1.5, 1.4}}});
  const BlockNetwork net = build_block_network({kSquare, traces, {}, 0.0, 0.0});
  ASSERT_EQ(net.blocks.size(), 1u);
  EXPECT_NEAR(total_area(net.blocks), 16.0, 1e-12);
  EXPECT_EQ(net.dropped_from, (std::vector<int>{0, 1, 2, 3}));
  // Joined to the boundary by a trace, the loop's outside is one face on both sides of the
  // joining trace (a bridge): it is dropped, and then the island.
  auto bridged = traces;
  bridged.push_back({{{0, 2}, {1.5, 2}}, {}});
  const BlockNetwork b = build_block_network({kSquare, bridged, {}, 0.0, 0.0});
  ASSERT_EQ(b.blocks.size(), 1u);
  EXPECT_EQ(b.dropped_from.size(), 5u);
  // Joined to the boundary on two sides, the loop is a block and so is each part around it.
  bridged.push_back({{{1.5, 2}, {4, 2}}, {}});
  const BlockNetwork c = build_block_network({kSquare, bridged, {}, 0.0, 0.0});
  EXPECT_EQ(c.blocks.size(), 4u);
  EXPECT_NEAR(total_area(c.blocks), 16.0, 1e-12);
}

TEST(BlockNetwork, AClusterTouchingTheRestAtOnePointIsDropped) {
  // A triangle hanging from the trace y = 2 by its apex (2, 2) only: the block below goes
  // round it and meets itself at the apex, a block with a hole pinched at a point. The
  // triangle's traces are dropped like an island: two blocks, both simple.
  const auto traces = listed({{{0, 2}, {4, 2}}, {{2, 2}, {1.45, 0.9}}, {{2, 2}, {2.55, 0.9}}, {{1.4, 1}, {2.6, 1}}});
  const BlockNetwork net = build_block_network({kSquare, traces, {}, 0.0, 0.0});
  ASSERT_EQ(net.blocks.size(), 2u);
  for (const Polygon& p : net.blocks) EXPECT_FALSE(find_self_intersection(p).has_value());
  EXPECT_NEAR(total_area(net.blocks), 16.0, 1e-12);
  EXPECT_EQ(net.dropped_from, (std::vector<int>{1, 2, 3}));
}

TEST(BlockNetwork, SliverMergesIntoTheNeighbourWithTheLongestSharedEdge) {
  // Traces at x = 1 and x = 1.002 across the square, and y = 2 from x = 0 to the second
  // trace: slivers 0.002 × 2 between the traces. Each shares 2 m with the block to its left
  // and right and 0.002 m with the other sliver: merged into the left block (the first of
  // two equal ones in the blocks' order) — two merges, three blocks.
  const auto traces = listed({{{1, 0}, {1, 4}}, {{1.002, 0}, {1.002, 4}}, {{0, 2}, {1.002, 2}}});
  const BlockNetwork net = build_block_network({kSquare, traces, {}, 0.0, 0.0});
  EXPECT_EQ(net.cut_blocks, 5);
  EXPECT_EQ(net.merged_small, 2);
  ASSERT_EQ(net.blocks.size(), 3u);
  EXPECT_NEAR(total_area(net.blocks), 16.0, 1e-12);
  EXPECT_NEAR(net.min_block_area, 0.01 * 16.0 / 5.0, 1e-15);
  for (const Polygon& p : net.blocks) EXPECT_GE(signed_area(p), net.min_block_area);
  // A threshold given explicitly keeps them.
  const BlockNetwork kept = build_block_network({kSquare, traces, {}, 1e-3, 0.0});
  EXPECT_EQ(kept.blocks.size(), 5u);
}

// Random short traces (1 to 3 m) in a 30 m square, seeded: 1,500 make some two thousand
// blocks, with slivers. Directions from uniform draws and a square root only, so the same
// traces on every machine.
std::vector<FractureTrace> random_short_traces(int count, std::uint64_t seed) {
  PortableRandom random(seed);
  std::vector<FractureTrace> traces;
  while (static_cast<int>(traces.size()) < count) {
    const Point middle{30.0 * random.uniform(), 30.0 * random.uniform()};
    const Point d{random.uniform() - 0.5, random.uniform() - 0.5};
    const double norm = std::sqrt(dot(d, d)), half = 0.5 + random.uniform();
    if (norm < 0.1 || norm > 0.5) continue;  // uniform directions: inside a ring
    const Point along = (half / norm) * d;
    traces.push_back({{middle - along, middle + along}, {TraceSource::file, -1, static_cast<int>(traces.size()) + 1}});
  }
  return traces;
}

// The blocks' vertices (to a nanometre) and edges' fractures, hashed (FNV-1a).
std::uint64_t hash_blocks(const BlockNetwork& net) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  const auto mix = [&](std::int64_t v) { h = (h ^ static_cast<std::uint64_t>(v)) * 0x100000001b3ull; };
  for (std::size_t b = 0; b < net.blocks.size(); ++b) {
    mix(static_cast<std::int64_t>(net.blocks[b].size()));
    for (std::size_t k = 0; k < net.blocks[b].size(); ++k) {
      mix(std::llround(net.blocks[b][k].x * 1e9));
      mix(std::llround(net.blocks[b][k].y * 1e9));
      mix(net.edge_fractures[b][k]);
    }
  }
  return h;
}

TEST(BlockNetwork, SliversOfARandomNetworkMergeAsBefore) {
  // 1,500 random traces: the blocks and counts the merging made when it scanned every block
  // for the smallest sliver and for its neighbours (measured then), as it keeps its own now.
  const Polygon square{{0, 0}, {30, 0}, {30, 30}, {0, 30}};
  const BlockNetwork net = build_block_network({square, random_short_traces(1500, 5), {}, 0.0, 0.0});
  EXPECT_EQ(net.cut_blocks, 1710);
  EXPECT_EQ(net.merged_small, 420);
  EXPECT_EQ(net.unmerged_small, 0);
  EXPECT_EQ(net.blocks.size(), 1290u);
  EXPECT_EQ(net.faces.size(), 4079u);
  EXPECT_EQ(hash_blocks(net), 0x2b65def46b111e4full);
  // A smaller threshold and a 5 cm aperture: most merges are of blocks too thin for it.
  const BlockNetwork opened = build_block_network({square, random_short_traces(1500, 5), {}, 1e-4, 0.05});
  EXPECT_EQ(opened.merged_small, 69);
  EXPECT_EQ(opened.merged_thin, 862);
  EXPECT_EQ(opened.blocks.size(), 779u);
  EXPECT_EQ(opened.faces.size(), 3344u);
  EXPECT_EQ(hash_blocks(opened), 0xbac29cd63272f44dull);
}

TEST(BlockNetwork, EachMergeLooksAtItsNeighboursOnly) {
  // The merges' work grows with the slivers, not with the blocks times the slivers: on
  // networks of 1,700 and 7,000 blocks, the blocks looked at per merge stay a handful (a
  // block's neighbours and its turn in the queue), where a scan of every block would look at
  // thousands. With an aperture, the thin blocks' merges too.
  const Polygon square{{0, 0}, {30, 0}, {30, 30}, {0, 30}};
  for (int count : {1500, 3000}) {
    for (double aperture : {0.0, 0.01}) {
      SCOPED_TRACE(std::to_string(count) + " traces, aperture " + std::to_string(aperture));
      const BlockNetwork net = build_block_network({square, random_short_traces(count, 5), {}, 0.0, aperture});
      const int merges = net.merged_small + net.merged_thin + net.unmerged_small;
      ASSERT_GT(net.cut_blocks, 1000);
      ASSERT_GT(merges, 100);
      EXPECT_LT(static_cast<double>(net.merge_visits) / merges, 12.0) << net.merge_visits << " visits, " << merges << " merges";
    }
  }
}

TEST(BlockNetwork, BlocksTooThinForTheApertureAreMerged) {
  // A strip 4 mm thick between two traces, kept by a small min_block_area: an aperture of
  // 5 mm would turn it inside out, so it joins a neighbour; the two blocks left are 5 mm apart.
  const auto traces = listed({{{0, 2}, {4, 2}}, {{0, 2.004}, {4, 2.004}}});
  const BlockNetwork net = build_block_network({kSquare, traces, {}, 1e-6, 0.005});
  EXPECT_EQ(net.merged_thin, 1);
  ASSERT_EQ(net.blocks.size(), 2u);
  EXPECT_NEAR(16.0 - total_area(net.blocks), 4 * 0.005, 1e-12);
  // An aperture larger than every block: all merge into one, which has no fracture face left.
  const BlockNetwork one = build_block_network({kSquare, listed({{{2, 0}, {2, 4}}, {{0, 2}, {4, 2}}}), {}, 0.0, 5.0});
  ASSERT_EQ(one.blocks.size(), 1u);
  EXPECT_EQ(one.merged_thin, 3);
  EXPECT_NEAR(total_area(one.blocks), 16.0, 1e-12);
}

TEST(BlockNetwork, TracesMeetingAtTinyAnglesLeaveNoSliver) {
  // Two traces from one point of the left side, 0.2° apart, across the square: a wedge of
  // 0.5 × 4² × tan 0.2° = 0.028 m², under 1% of the mean block area (16/3): merged.
  const double t = std::tan(0.2 * 3.141592653589793 / 180.0);
  const auto traces = listed({{{0, 1}, {4, 1}}, {{0, 1}, {4, 1 + 4 * t}}});
  const BlockNetwork net = build_block_network({kSquare, traces, {}, 0.0, 0.001});
  ASSERT_EQ(net.blocks.size(), 2u);
  EXPECT_EQ(net.merged_small, 1);
  for (const Polygon& p : net.blocks) {
    EXPECT_GT(signed_area(p), 0.0);
    EXPECT_FALSE(find_self_intersection(p).has_value());
  }
}

// Random joint sets over many seeds: the blocks tile the domain (their areas sum to the
// domain's within 1e-9 relative before the aperture), none is below the minimum area, every
// one is simple and counter-clockwise, and each edge lies on its fracture or on the boundary.
// With the aperture, every block is still simple, counter-clockwise and at least half its
// unshrunk area, and the blocks cover less than the domain.
TEST(BlockNetwork, RandomJointSetsTileTheDomain) {
  const Polygon domain{{0, 0}, {10, 0}, {10, 4}, {7, 6}, {0, 6}};
  const double domain_area = signed_area(domain);
  int total_blocks = 0, total_merged = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    std::vector<FractureTrace> traces;
    for (int s = 0; s < 2; ++s) {
      JointSet set;
      set.angle = s == 0 ? 25.0 : 115.0;
      set.angle_spread = 8.0;
      set.spacing = s == 0 ? 0.8 : 1.1;
      set.spacing_spread = 0.4;
      set.length = 3.0;
      set.length_spread = 1.5;
      set.gap = 1.0;
      set.region = domain;
      set.seed = seed * 2 + static_cast<std::uint64_t>(s);
      const auto segments = generate_joint_traces(set);
      for (std::size_t k = 0; k < segments.size(); ++k)
        traces.push_back({segments[k], {TraceSource::joint_set, s, static_cast<int>(k)}});
    }
    const BlockNetwork net = build_block_network({domain, traces, {}, 0.0, 0.0});
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_NEAR(total_area(net.blocks), domain_area, 1e-9 * domain_area);
    EXPECT_EQ(net.unmerged_small, 0);
    total_blocks += static_cast<int>(net.blocks.size());
    total_merged += net.merged_small;
    for (std::size_t b = 0; b < net.blocks.size(); ++b) {
      const Polygon& p = net.blocks[b];
      EXPECT_GE(signed_area(p), net.min_block_area);
      EXPECT_FALSE(find_self_intersection(p).has_value());
      for (std::size_t e = 0; e < p.size(); ++e) {
        const Point a = p[e], c = p[(e + 1) % p.size()];
        const int f = net.edge_fractures[b][e];
        if (f < 0) {
          EXPECT_TRUE(on_domain_boundary(0.5 * (a + c), domain, 1e-8));
        } else {
          const Segment2& s = traces[f].segment;
          EXPECT_LE(distance_to_segment(a, s.from, s.to), 1e-8);
          EXPECT_LE(distance_to_segment(c, s.from, s.to), 1e-8);
        }
      }
    }
    const BlockNetwork shrunk = build_block_network({domain, traces, {}, 0.0, 0.01});
    EXPECT_LT(total_area(shrunk.blocks), domain_area);
    for (const Polygon& p : shrunk.blocks) {
      EXPECT_GT(signed_area(p), 0.0);
      EXPECT_FALSE(find_self_intersection(p).has_value());
    }
  }
  // The sets do make slivers to merge, and blocks.
  EXPECT_GT(total_merged, 20);
  EXPECT_GT(total_blocks, 60 * 10);
}

}  // namespace
}  // namespace hydrodda::geometry
