#include "hydro/region_tensor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <stdexcept>
#include <vector>

#include "hydro/flow_failure.hpp"
#include "hydro/linear_solver.hpp"

namespace hydrodda::hydro {

using geometry::Point;

namespace {

// Why a region's tensor could not be solved for, in the model's terms: the contrast it met.
std::string describe_conductivity_contrast(std::span<const Conductivity> conductivity, std::span<const int> triangles) {
  double least = INFINITY, largest = -INFINITY;
  for (int t : triangles) {
    const Conductivity& k = conductivity[t];
    least = std::min({least, k.xx, k.yy});
    largest = std::max({largest, k.xx, k.yy});
  }
  char text[160];
  std::snprintf(text, sizeof text, "the region's conductivity spans %.3g to %.3g m/s, a contrast its solve could not "
                "resolve in double precision", least, largest);
  return std::string("a flow region's effective conductivity tensor could not be solved for: ") + text;
}

}  // namespace

EffectiveTensor compute_region_tensor(const mesh::TriangleMesh& mesh, std::span<const Conductivity> conductivity,
                                      std::span<const int> triangles) {
  if (triangles.empty()) throw std::runtime_error("region tensor: the region has no triangles");
  if (conductivity.size() != mesh.triangles.size())
    throw std::invalid_argument("region tensor: one conductivity per mesh triangle is needed");
  std::vector<std::array<int, 3>> local;
  for (int t : triangles) local.push_back(mesh.triangles[t]);
  // Nodes on the region's boundary take the affine heads; the others are unknowns.
  std::vector<char> on_boundary(mesh.nodes.size(), 0);
  for (const auto& edge : mesh::find_boundary_edges(local)) on_boundary[edge[0]] = on_boundary[edge[1]] = 1;
  std::vector<int> unknown(mesh.nodes.size(), -1);
  int n = 0;
  for (const auto& tri : local)
    for (int v : tri)
      if (!on_boundary[v] && unknown[v] < 0) unknown[v] = n++;

  // Assemble the free-free block (upper triangle) and, per direction, the right-hand side
  // −K_fb u_b with u_b = x or y at the boundary nodes.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs_x = Eigen::VectorXd::Zero(n), rhs_y = Eigen::VectorXd::Zero(n);
  std::vector<std::array<std::array<double, 3>, 3>> element(local.size());
  for (std::size_t k = 0; k < local.size(); ++k) {
    const auto& tri = local[k];
    element[k] = compute_element_matrix(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]],
                                        conductivity[triangles[k]]);
    for (int i = 0; i < 3; ++i) {
      const int row = unknown[tri[i]];
      if (row < 0) continue;
      for (int j = 0; j < 3; ++j) {
        const int column = unknown[tri[j]];
        if (column >= 0) {
          if (row <= column) entries.emplace_back(row, column, element[k][i][j]);
        } else {
          rhs_x[row] -= element[k][i][j] * mesh.nodes[tri[j]].x;
          rhs_y[row] -= element[k][i][j] * mesh.nodes[tri[j]].y;
        }
      }
    }
  }
  Eigen::VectorXd u_x, u_y;
  if (n > 0) {
    SparseMatrix upper(n, n);
    upper.setFromTriplets(entries.begin(), entries.end());
    std::unique_ptr<numerics::SparseCholesky> solver = make_cholmod_solver(FillOrdering::automatic);
    solver->analyse(upper);
    try {
      solver->factorize(upper);
    } catch (const SingularSystem&) {
      throw FlowSolveFailed(describe_conductivity_contrast(conductivity, triangles));
    }
    u_x = solver->solve(rhs_x);
    u_y = solver->solve(rhs_y);
  }
  auto head = [&](int node, bool along_x) {
    const int i = unknown[node];
    if (i >= 0) return along_x ? u_x[i] : u_y[i];
    return along_x ? mesh.nodes[node].x : mesh.nodes[node].y;
  };
  // K_eff,ij = (1/A) Σ_e u_iᵀ K_e u_j, the energy form of the two solutions.
  double area = 0.0, xx = 0.0, xy = 0.0, yy = 0.0;
  for (std::size_t k = 0; k < local.size(); ++k) {
    const auto& tri = local[k];
    area += mesh::triangle_area(mesh, triangles[k]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double a = element[k][i][j];
        xx += head(tri[i], true) * a * head(tri[j], true);
        xy += head(tri[i], true) * a * head(tri[j], false);
        yy += head(tri[i], false) * a * head(tri[j], false);
      }
  }
  return principal_axes({xx / area, xy / area, yy / area});
}

// Eigen-decomposition of [[a, b], [b, c]]: λ = m ± r, m = (a + c)/2, r = √(((a − c)/2)² + b²);
// the major axis at θ = ½ atan2(2b, a − c) from x.
EffectiveTensor principal_axes(const Conductivity& k) {
  EffectiveTensor out;
  out.tensor = k;
  const double mean = 0.5 * (k.xx + k.yy), half_difference = 0.5 * (k.xx - k.yy);
  const double radius = std::sqrt(half_difference * half_difference + k.xy * k.xy);
  out.principal = {mean + radius, mean - radius};
  const double theta = 0.5 * std::atan2(2.0 * k.xy, k.xx - k.yy);
  Point major{std::cos(theta), std::sin(theta)};
  if (major.x < 0.0 || (major.x == 0.0 && major.y < 0.0)) major = -1.0 * major;
  Point minor{-major.y, major.x};
  if (minor.x < 0.0 || (minor.x == 0.0 && minor.y < 0.0)) minor = -1.0 * minor;
  out.directions = {major, minor};
  return out;
}

}  // namespace hydrodda::hydro
