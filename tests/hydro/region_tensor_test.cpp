// The region's effective conductivity tensor by two auxiliary solves with linear head
// conditions (hydro/region_tensor.hpp), against exact cases.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "flow_test_meshes.hpp"
#include "hydro/region_tensor.hpp"

namespace hydrodda::hydro {
namespace {

// The unit square in n × n cells, each cut along a diagonal (alternating), so that y = 0.5 is a
// line of element edges for even n.
mesh::TriangleMesh make_square_grid(int n) {
  mesh::TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.nodes.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n});
  const auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) m.triangles.push_back({a, b, c}), m.triangles.push_back({a, c, d});
      else m.triangles.push_back({a, b, d}), m.triangles.push_back({b, c, d});
    }
  m.region.assign(m.triangles.size(), 0);
  m.region_names = {"domain"};
  return m;
}

std::vector<int> all_triangles(const mesh::TriangleMesh& m) {
  std::vector<int> t(m.triangles.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = static_cast<int>(i);
  return t;
}

TEST(RegionTensor, UniformAnisotropicTensorIsReturnedWithItsAxes) {
  // A uniform K = R diag(k1, k2) Rᵀ, R a turn by 30°: the affine heads solve the problem
  // exactly (∇·(K∇u) = 0 for u linear), so K_eff = K and its principal values and axes are
  // k1, k2 at 30° and 120°, to round-off (1e-10 relative) on an unstructured mesh.
  const mesh::TriangleMesh m = testing::make_rectangle_mesh(2.0, 1.0, 0.1);
  const double k1 = 3e-4, k2 = 2e-6, theta = std::numbers::pi / 6;
  const double c = std::cos(theta), s = std::sin(theta);
  const Conductivity k{k1 * c * c + k2 * s * s, (k1 - k2) * c * s, k1 * s * s + k2 * c * c};
  const std::vector<Conductivity> field(m.triangles.size(), k);
  const EffectiveTensor t = compute_region_tensor(m, field, all_triangles(m));
  EXPECT_NEAR(t.tensor.xx, k.xx, 1e-10 * k1);
  EXPECT_NEAR(t.tensor.xy, k.xy, 1e-10 * k1);
  EXPECT_NEAR(t.tensor.yy, k.yy, 1e-10 * k1);
  EXPECT_NEAR(t.principal[0], k1, 1e-10 * k1);
  EXPECT_NEAR(t.principal[1], k2, 1e-10 * k1);
  EXPECT_NEAR(t.directions[0].x, c, 1e-8);
  EXPECT_NEAR(t.directions[0].y, s, 1e-8);
  EXPECT_NEAR(t.directions[1].x * c + t.directions[1].y * s, 0.0, 1e-8);
}

TEST(RegionTensor, LayersGiveTheArithmeticMeanAlongAndABoundAcross) {
  // Horizontal layers: the lower half K_a, the upper half K_b, the interface y = 0.5 a line of
  // element edges. Along the layers u = x is the exact solution (no flux crosses a straight
  // interface parallel to the gradient): K_xx = (K_a + K_b)/2, the arithmetic mean, to
  // round-off. Across,
  // linear conditions hold the sides' heads linear, so K_yy lies between the harmonic mean of the
  // layers (the exact series value) and the arithmetic mean (Voigt's bound).
  const mesh::TriangleMesh m = make_square_grid(20);
  const double ka = 1e-3, kb = 1e-6;
  std::vector<Conductivity> field;
  double area = 0.0, sum_k_area = 0.0, sum_area_over_k = 0.0;
  for (int t = 0; t < m.triangle_count(); ++t) {
    const double k = mesh::triangle_centroid(m, t).y < 0.5 ? ka : kb;
    const double a = mesh::triangle_area(m, t);
    field.push_back({k, 0.0, k});
    area += a, sum_k_area += k * a, sum_area_over_k += a / k;
  }
  const EffectiveTensor t = compute_region_tensor(m, field, all_triangles(m));
  const double arithmetic = sum_k_area / area, harmonic = area / sum_area_over_k;
  EXPECT_NEAR(t.tensor.xx, arithmetic, 1e-10 * arithmetic);
  EXPECT_GT(t.tensor.yy, harmonic);
  EXPECT_LT(t.tensor.yy, arithmetic);
  EXPECT_GE(t.principal[0], t.principal[1]);
}

TEST(RegionTensor, PrincipalAxesOfADiagonalTensor) {
  const EffectiveTensor t = principal_axes({1.0, 0.0, 4.0});
  EXPECT_EQ(t.principal[0], 4.0);
  EXPECT_EQ(t.principal[1], 1.0);
  EXPECT_NEAR(t.directions[0].x, 0.0, 1e-15);
  EXPECT_NEAR(t.directions[0].y, 1.0, 1e-15);
  EXPECT_NEAR(t.directions[1].x, 1.0, 1e-15);
}

}  // namespace
}  // namespace hydrodda::hydro
