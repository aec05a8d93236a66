#include "dda/support.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "geometry/polygon.hpp"

namespace hydrodda::dda {

namespace {

using geometry::Point;
using geometry::Polygon;

// Union–find over block indices, the smaller index as each set's root.
struct Groups {
  std::vector<int> parent;
  explicit Groups(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int root(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) {
    a = root(a);
    b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Some vertex of one polygon within `distance` of an edge of the other.
bool touching(const Polygon& a, const Polygon& b, double distance) {
  const auto near = [distance](const Polygon& from, const Polygon& to) {
    for (Point p : from)
      for (std::size_t i = 0; i < to.size(); ++i)
        if (geometry::distance_to_segment(p, to[i], to[(i + 1) % to.size()]) <= distance) return true;
    return false;
  };
  return near(a, b) || near(b, a);
}

double half_model_height(const std::vector<BlockDefinition>& blocks) {
  geometry::Box all;
  for (const BlockDefinition& b : blocks)
    for (Point p : b.polygon) all.add(p);
  return 0.5 * std::max(all.height(), 1e-3 * all.width());
}

}  // namespace

double initial_contact_distance(const std::vector<BlockDefinition>& blocks, const Settings& settings) {
  if (settings.contact_distance > 0) return settings.contact_distance;
  return 2.5 * settings.max_displacement_ratio * half_model_height(blocks);
}

double initial_penetration_tolerance(const std::vector<BlockDefinition>& blocks, const Settings& settings) {
  if (settings.penetration_tolerance > 0) return settings.penetration_tolerance;
  return 1e-4 * settings.max_displacement_ratio * half_model_height(blocks);
}

double displacement_ratio_for_blocks(const std::vector<BlockDefinition>& blocks, double ratio) {
  if (blocks.empty()) return ratio;
  double thinnest = std::numeric_limits<double>::infinity();
  for (const BlockDefinition& b : blocks) thinnest = std::min(thinnest, geometry::width_across_edges(b.polygon));
  const double w0 = half_model_height(blocks);
  if (!(thinnest > 0.0) || !(w0 > 0.0)) return ratio;
  // 2.5 r w0 ≤ w_min / 2.
  return std::min(ratio, 0.2 * thinnest / w0);
}

std::vector<std::vector<int>> find_unsupported_groups(const ModelDefinition& model, double touching_distance) {
  const int n = static_cast<int>(model.blocks.size());
  Groups groups(n);
  // Sweep along x over the boxes, grown by the distance, so that only neighbours are compared.
  std::vector<geometry::Box> boxes;
  for (const BlockDefinition& b : model.blocks) boxes.push_back(geometry::bounding_box(b.polygon).inflated(touching_distance));
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return boxes[i].lo.x < boxes[j].lo.x || (boxes[i].lo.x == boxes[j].lo.x && i < j);
  });
  for (int oi = 0; oi < n; ++oi) {
    const int i = order[oi];
    for (int oj = oi + 1; oj < n; ++oj) {
      const int j = order[oj];
      if (boxes[j].lo.x > boxes[i].hi.x) break;
      if (!boxes[i].overlaps(boxes[j]) || groups.root(i) == groups.root(j)) continue;
      if (touching(model.blocks[i].polygon, model.blocks[j].polygon, touching_distance)) groups.join(i, j);
    }
  }

  std::vector<bool> supported(n, false);
  const auto hold = [&](int block) { supported[groups.root(block)] = true; };
  for (int b = 0; b < n; ++b)
    if (model.blocks[b].fixed) hold(b);
  for (const FixedPoint& f : model.fixed_points) hold(f.block);
  for (const PrescribedDisplacement& d : model.displacements) hold(d.block);
  for (const Roller& r : model.rollers) hold(r.block);

  std::vector<std::vector<int>> unsupported;
  std::vector<int> slot(n, -1);
  for (int b = 0; b < n; ++b) {
    const int root = groups.root(b);
    if (supported[root]) continue;
    if (slot[root] < 0) {
      slot[root] = static_cast<int>(unsupported.size());
      unsupported.emplace_back();
    }
    unsupported[slot[root]].push_back(b);
  }
  return unsupported;
}

}  // namespace hydrodda::dda
