#pragma once
// Small models shared by the DDA tests.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "dda/block_matrix.hpp"
#include "dda/definitions.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::dda::testing {

inline Polygon make_rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A rectangle [u0,u1]×[w0,w1] in the frame of a slope at theta (t along, n normal to it).
inline Polygon make_slope_rectangle(double theta, double u0, double w0, double u1, double w1) {
  const Point t{std::cos(theta), std::sin(theta)};
  const Point n{-std::sin(theta), std::cos(theta)};
  Polygon out;
  for (Point p : make_rectangle(u0, w0, u1, w1)) out.push_back(p.x * t + p.y * n);
  return out;
}

// A 1 m × 1 m block (ρ 2500, E 10 GPa, ν 0.25) on a fixed 20 m incline at theta_deg.
inline ModelDefinition make_incline(double theta_deg, double phi_deg, double cohesion) {
  const double theta = theta_deg * std::numbers::pi / 180.0;
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  m.blocks.push_back({make_slope_rectangle(theta, 0.0, -1.0, 20.0, 0.0), 0, true});
  m.blocks.push_back({make_slope_rectangle(theta, 15.0, 0.0, 16.0, 1.0), 0, false});
  m.joint = {phi_deg, cohesion, 0.0};
  m.settings.analysis = Analysis::dynamic;
  m.settings.time_step = 1.0e-3;
  return m;
}

// rows × cols cells of a lattice with jittered nodes (±0.2 m on 1 m), each cell shrunk by
// 0.1% about its centroid: irregular quadrilaterals 0.5 mm apart, 0.5 mm above a fixed base,
// to fall and settle under gravity (dynamic, Δt 1 ms).
inline ModelDefinition make_random_packing(int rows, int cols) {
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  m.joint = {30.0, 0.0, 0.0};
  m.settings.analysis = Analysis::dynamic;
  m.settings.time_step = 1.0e-3;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Point> nodes((rows + 1) * (cols + 1));
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) {
      const bool edge_x = i == 0 || i == cols;
      nodes[j * (cols + 1) + i] = {i + (edge_x ? 0.0 : jitter(rng)), 0.0015 + j + (j == 0 ? 0.0 : jitter(rng))};
    }
  m.blocks.push_back({make_rectangle(-1.0, -1.0, cols + 1.0, 0.0), 0, true});
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      Polygon p{nodes[j * (cols + 1) + i], nodes[j * (cols + 1) + i + 1], nodes[(j + 1) * (cols + 1) + i + 1],
                nodes[(j + 1) * (cols + 1) + i]};
      const Point c = geometry::centroid(p);
      for (Point& v : p) v = c + 0.999 * (v - c);
      m.blocks.push_back({p, 0, false});
    }
  return m;
}

inline ModelDefinition make_random_packing(int n) { return make_random_packing(n, n); }

// A staggered brick wall of rows × cols 2 m × 1 m bricks on a fixed base, as the peer
// generator brickwall.py writes it.
inline ModelDefinition make_brick_wall(int rows, int cols) {
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  m.joint = {30.0, 0.0, 0.0};
  m.blocks.push_back({make_rectangle(-1.0, -1.0, 2.0 * cols + 2, 0.0), 0, true});
  for (int r = 0; r < rows; ++r) {
    const double off = r % 2 == 0 ? 0.0 : 1.0;
    std::vector<double> edges{0.0};
    for (int k = 1; k <= cols; ++k)
      if (off + 2.0 * k < 2.0 * cols) edges.push_back(off + 2.0 * k);
    edges.push_back(2.0 * cols);
    for (std::size_t k = 0; k + 1 < edges.size(); ++k)
      if (edges[k + 1] > edges[k]) m.blocks.push_back({make_rectangle(edges[k], r, edges[k + 1], r + 1.0), 0, false});
  }
  m.settings.analysis = Analysis::static_;
  m.settings.time_step = 1.0e-3;
  return m;
}

// A symmetric positive definite matrix on a block graph of n blocks: each joint (i, j), i < j,
// sorted, adds Gᵀ G for a random 6 × 12 G over its two blocks, the diagonal the identity
// besides. The same joints and seed give the same matrix.
inline BlockMatrix make_block_graph_matrix(int n, const std::vector<std::pair<int, int>>& joints,
                                           unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BlockMatrix a;
  a.block_count = n;
  a.diagonal.assign(n, Matrix6::Identity());
  for (auto [i, j] : joints) {
    Eigen::Matrix<double, 6, 12> g;
    for (int k = 0; k < g.size(); ++k) g.data()[k] = u(rng);
    const Eigen::Matrix<double, 12, 12> gg = g.transpose() * g;
    a.diagonal[i] += gg.topLeftCorner<6, 6>();
    a.diagonal[j] += gg.bottomRightCorner<6, 6>();
    a.pairs.emplace_back(i, j);
    a.off.push_back(gg.bottomLeftCorner<6, 6>());
  }
  return a;
}

// A matrix on the block graph of a rows × rows staggered wall (each brick joined to its two
// neighbours in the row and two in each row above and below), each joint adding Gᵀ G for a
// random 6 × 12 G, plus the identity: the pattern, and so the fill, of the wall's matrix.
inline BlockMatrix make_wall_graph_matrix(int rows) {
  std::vector<std::pair<int, int>> joints;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < rows; ++c) {
      const int b = r * rows + c;
      if (c + 1 < rows) joints.emplace_back(b, b + 1);
      if (r + 1 < rows) {
        joints.emplace_back(b, b + rows);
        const int shifted = r % 2 == 0 ? c - 1 : c + 1;
        if (shifted >= 0 && shifted < rows) joints.emplace_back(b, (r + 1) * rows + shifted);
      }
    }
  std::sort(joints.begin(), joints.end());
  return make_block_graph_matrix(rows * rows, joints, 21);
}

// A fixed base [0, 1] × [−1, 0] and a 1 m × 1 m sub-block on it, their shared face (the
// base's top edge 2, the block's bottom edge 0) bonded by a face of type `bond`, no gravity,
// static analysis, Δt 1 ms. The face's traction is the free sub-block's stress (the fixed base
// carries none).
inline ModelDefinition make_bonded_block(const Joint& bond, const Material& material = {2500.0, 1.0e10, 0.25}) {
  ModelDefinition m;
  m.materials = {material};
  BlockDefinition base{make_rectangle(0.0, -1.0, 1.0, 0.0), 0, true};
  BlockDefinition block{make_rectangle(0.0, 0.0, 1.0, 1.0), 0, false};
  base.edge_joints = {0, 0, 1, 0};
  base.edge_bonds = {-1, -1, 0, -1};
  block.edge_joints = {1, 0, 0, 0};
  block.edge_bonds = {0, -1, -1, -1};
  m.blocks = {base, block};
  m.joint = {30.0, 0.0, 0.0};
  m.joint_types = {bond};
  m.settings.analysis = Analysis::static_;
  m.settings.gravity = {0.0, 0.0};
  m.settings.time_step = 1e-3;
  return m;
}

}  // namespace hydrodda::dda::testing
