#pragma once
// Generated fracture traces: a joint set of given orientation, spacing and trace length, with
// spreads, placed in a region by a seeded generator that gives the same joints on every
// machine (portable_random.hpp).

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/polygon.hpp"

namespace hydrodda::geometry {

struct JointSet {
  double angle = 0.0;              // degrees counter-clockwise from +x
  double spacing = 1.0;            // m, between joints, measured along the set's normal
  double angle_spread = 0.0;       // degrees, standard deviation of each joint's angle
  double spacing_spread = 0.0;     // m, standard deviation of each spacing
  std::optional<double> length;    // m, mean trace length; empty: persistent across the region
  double length_spread = 0.0;      // m
  std::optional<double> gap;       // m, mean rock bridge between traces along a joint; empty: length
  double gap_spread = 0.0;         // m
  std::optional<double> offset;    // m, first joint from the lowest corner; empty: spacing / 2
  Polygon region;                  // counter-clockwise
  std::uint64_t seed = 0;
};

// The set's unit normal, turned upward (+y; +x for a vertical set): the axis its spacing and
// offset are measured along.
Point joint_set_normal(double angle_degrees);

// The region's lowest corner for the set: its vertex with the smallest n · p along the set's
// normal n (of several, the one that comes first along the set's direction).
Point find_lowest_corner(const Polygon& region, double angle_degrees);

// The set's traces inside its region, in the order they are made.
//
//   n, d = the set's normal and direction; c = the lowest corner; s = offset
//   while s ≤ the region's extent along n:
//     the joint's angle a = angle + angle_spread · z; it passes through the point at s along
//       the normal axis through the region's centroid (a spread angle turns it about there)
//     persistent: the line's parts inside the region are traces
//     else: from a random phase before the region, along the line: a trace of length
//       length + length_spread · z, then a rock bridge of gap + gap_spread · z, and so on past
//       the region; each trace's parts inside the region are traces
//     s += spacing + spacing_spread · z
// z are standard normal draws; a spacing, length or gap below a tenth of its mean is drawn
// again. Throws std::invalid_argument when the set would make more than `max_traces`.
std::vector<Segment2> generate_joint_traces(const JointSet& set, std::size_t max_traces = 100'000);

}  // namespace hydrodda::geometry
