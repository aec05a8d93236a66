// Block kernels against hand-computed values and exact identities.

#include "dda/block_kernels.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_rectangle;

// Rectangle w × h: A = wh, ∫X² = w³h/12, ∫Y² = wh³/12, ∫XY = 0 about its centroid (exact).
TEST(BlockKernels, RectangleMomentsAreExact) {
  const Moments m = compute_moments(make_rectangle(1, 2, 4, 4));
  EXPECT_DOUBLE_EQ(m.area, 6.0);
  EXPECT_DOUBLE_EQ(m.centroid.x, 2.5);
  EXPECT_DOUBLE_EQ(m.centroid.y, 3.0);
  EXPECT_NEAR(m.sxx, 27.0 * 2 / 12, 1e-12);
  EXPECT_NEAR(m.syy, 3.0 * 8 / 12, 1e-12);
  EXPECT_NEAR(m.sxy, 0.0, 1e-12);
}

// Mass matrix: M00 = M11 = ρA; rotational inertia M22 = ρ(∫X² + ∫Y²); symmetric.
TEST(BlockKernels, MassMatrixHasMassAndPolarInertia) {
  const Moments m = compute_moments(make_rectangle(0, 0, 2, 1));
  const Matrix6 mass = compute_mass_matrix(m, 3.0);
  EXPECT_NEAR(mass(0, 0), 6.0, 1e-12);
  EXPECT_NEAR(mass(1, 1), 6.0, 1e-12);
  EXPECT_NEAR(mass(2, 2), 3.0 * (8.0 / 12 + 2.0 / 12), 1e-12);
  EXPECT_NEAR(mass(0, 2), 0.0, 1e-12);
  EXPECT_LT((mass - mass.transpose()).norm(), 1e-12);
}

// M = ρ ∫ TᵀT dA against an independent quadrature, on a quadrilateral with no symmetry (so
// that ∫XY ≠ 0 and every entry the moments give is nonzero): the polygon cut into a fan of
// triangles, each integrated by its edge midpoints, ∫_T f = A_T/3 Σ f(midpoints), exact for
// the quadratic entries of TᵀT (Hammer, Marlowe & Stroud, Math. Tables Aids Comput. 10, 1956). To 1e-13 of the largest entry
// (round-off of sums of a few terms).
TEST(BlockKernels, MassMatrixIsTheIntegralOfTTransposeT) {
  const std::vector<Point> quad{{0.0, 0.0}, {2.5, 0.3}, {3.1, 1.9}, {0.4, 1.2}};
  const Moments m = compute_moments(quad);
  const double density = 2.7;
  Matrix6 expected = Matrix6::Zero();
  for (std::size_t t = 1; t + 1 < quad.size(); ++t) {
    const std::array<Point, 3> tri{quad[0], quad[t], quad[t + 1]};
    const double area = 0.5 * cross(tri[1] - tri[0], tri[2] - tri[0]);
    for (int e = 0; e < 3; ++e) {
      const Point mid = 0.5 * (tri[e] + tri[(e + 1) % 3]);
      const Matrix26 at = compute_displacement_matrix(mid, m.centroid);
      expected += density * area / 3.0 * at.transpose() * at;
    }
  }
  const Matrix6 mass = compute_mass_matrix(m, density);
  const double scale = expected.cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(mass(i, j), expected(i, j), 1e-13 * scale) << i << ", " << j;
  EXPECT_GT(std::abs(m.sxy), 0.1);
}

// T maps D to the point's displacement: a pure rotation r moves (x0+1, y0) by (0, r).
TEST(BlockKernels, DisplacementMatrixRotatesAboutTheCentroid) {
  Vector6 d;
  d << 0, 0, 0.01, 0, 0, 0;
  const Eigen::Vector2d u = compute_displacement_matrix({3, 2}, {2, 2}) * d;
  EXPECT_DOUBLE_EQ(u[0], 0.0);
  EXPECT_DOUBLE_EQ(u[1], 0.01);
}

// T·D written out is T·D: each of the six unknowns alone, and all at once, at a point off both
// axes through the centroid, agree with the matrix product to 1e-15 relative (round-off).
TEST(BlockKernels, WrittenOutDisplacementIsTheMatrixProduct) {
  const Point p{3.5, -1.25}, centroid{2.0, 0.5};
  for (int k = 0; k <= 6; ++k) {
    Vector6 d = Vector6::Zero();
    if (k < 6)
      d[k] = 0.01 * (k + 1);
    else
      d << 0.02, -0.03, 0.004, 0.005, -0.006, 0.007;
    const Eigen::Vector2d expected = compute_displacement_matrix(p, centroid) * d;
    const Point u = first_order_displacement(p, centroid, d);
    EXPECT_NEAR(u.x, expected[0], 1e-15 * expected.norm()) << "unknown " << k;
    EXPECT_NEAR(u.y, expected[1], 1e-15 * expected.norm()) << "unknown " << k;
  }
}

// Plane stress: σx = E/(1−ν²)(εx + ν εy); plane strain shear modulus E/(2(1+ν)).
TEST(BlockKernels, ElasticityMatricesMatchHookesLaw) {
  const Material mat{1000.0, 2.0e10, 0.25};
  const Eigen::Matrix3d s = compute_elasticity(mat, Plane::stress);
  EXPECT_NEAR(s(0, 0), 2.0e10 / (1 - 0.0625), 1.0);
  EXPECT_NEAR(s(0, 1), 0.25 * 2.0e10 / (1 - 0.0625), 1.0);
  const Eigen::Matrix3d p = compute_elasticity(mat, Plane::strain);
  EXPECT_NEAR(p(2, 2), 2.0e10 / (2 * 1.25), 1.0);
  EXPECT_NEAR(p(0, 0), 2.0e10 * 0.75 / (1.25 * 0.5), 1.0);
}

// Exact rotation: a block turned through a full revolution in 1000 steps keeps its area to
// 1e-9 relative and comes back to its start.
TEST(BlockKernels, FullRevolutionKeepsAreaAndShape) {
  Polygon p = make_rectangle(0, 0, 2, 1);
  const double a0 = geometry::area(p);
  Vector6 d;
  d << 0, 0, 2 * std::numbers::pi / 1000, 0, 0, 0;
  for (int i = 0; i < 1000; ++i) {
    const Point c = geometry::centroid(p);
    for (Point& v : p) v = displace_point(v, c, d);
  }
  EXPECT_NEAR(geometry::area(p), a0, 1e-9 * a0);
  EXPECT_NEAR(p[0].x, 0.0, 1e-9);
  EXPECT_NEAR(p[0].y, 0.0, 1e-9);
}

// Uniform normal traction σ on an edge of length L: force σ L n, no moment about the edge's
// midpoint. A linear traction from −q to +q: zero net force, moment q L²/6 about the midpoint.
TEST(BlockKernels, EdgeTractionGivesForceAndEndMoment) {
  const Point c{0.5, 0.5};
  // Top edge of the unit square, (1,1) → (0,1): outward normal (0, 1).
  const Vector6 f = compute_edge_traction_load({1, 1}, {0, 1}, c, -2.0, -2.0, 0, 0);
  EXPECT_NEAR(f[0], 0.0, 1e-12);
  EXPECT_NEAR(f[1], -2.0, 1e-12);
  EXPECT_NEAR(f[2], 0.0, 1e-12);  // midpoint is above the centroid: no moment
  // The elastic terms: εy work −2 × (y − y0) = −1; εx none.
  EXPECT_NEAR(f[4], -1.0, 1e-12);
  const Vector6 g = compute_edge_traction_load({1, 1}, {0, 1}, c, -3.0, 3.0, 0, 0);
  EXPECT_NEAR(g[1], 0.0, 1e-12);
  // Moment about the centroid (∫ x × t ds): traction −3 at x=1 rising to +3 at x=0:
  // t(x) = 3 − 6x, moment ∫ (x − 0.5) t dx = −0.5 = −q L²/6 with q = 3.
  EXPECT_NEAR(g[2], -0.5, 1e-12);
}

}  // namespace
}  // namespace hydrodda::dda
