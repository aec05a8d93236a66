// DarcySolver::solve_reusing_factor: conjugate gradients preconditioned by the factor of an
// earlier matrix, against the exact solve of the same matrix (solve(), a fresh factor and
// refinement). Both solve the same linear system, so their heads differ by the solvers'
// errors alone: the CG stopping rule bounds the head error by kHeadTolerance (1e-13) of the
// heads' range as far as the kept factor is the matrix, and the tests allow 1e-11 of the
// range (1 m here). Mass balance: never above the 1e-10 that every solve must meet; whenever
// CG's answer is kept, at most kBalanceTolerance (1e-12), or, for the oblique joints whose flow
// enters and leaves by one boundary, where the heads' round-off alone leaves more, at most
// twice the exact solve's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "hydro/darcy_solver.hpp"
#include "mesh/mesh_request.hpp"

namespace hydrodda::hydro {
namespace {

constexpr double kHeadAgreement = 1e-11;  // of the heads' range, 1 m
constexpr double kBalance = 1e-10;        // the bound every solve meets

// A fractured layer: the unit square, h = 1 at the bottom and 0 at the top, crossed by three
// horizontal and two vertical strips 4 mm wide ("fractures", k_f) in a matrix of 1e-14 m²:
// the flow crosses fractures and runs along them, so the heads depend on every strip.
struct Layer {
  mesh::TriangleMesh mesh;
  std::vector<int> fracture;  // per triangle: the strip it lies in (0–4), −1 in the matrix
};

const Layer& layer() {
  static const Layer l = [] {
    constexpr double w = 0.004;
    mesh::MeshRequest request;
    request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    request.size = 0.03;
    request.fracture_size = 0.004;
    request.refine_distance = 0.06;
    for (double y : {0.25, 0.5, 0.75}) request.refinement_lines.push_back({{0, y}, {1, y}});
    for (double x : {0.3, 0.7}) request.refinement_lines.push_back({{x, 0}, {x, 1}});
    Layer out;
    out.mesh = mesh::generate_mesh(request);
    out.fracture.assign(out.mesh.triangles.size(), -1);
    for (int t = 0; t < out.mesh.triangle_count(); ++t) {
      const geometry::Point c = mesh::triangle_centroid(out.mesh, t);
      for (int s = 0; s < 3; ++s)
        if (std::abs(c.y - 0.25 * (s + 1)) < w) out.fracture[t] = s;
      for (int s = 0; s < 2; ++s)
        if (std::abs(c.x - (s == 0 ? 0.3 : 0.7)) < w) out.fracture[t] = 3 + s;
    }
    return out;
  }();
  return l;
}

DarcyProblem bottom_to_top() {
  DarcyProblem p;
  p.boundaries = {{"bottom", BoundaryKind::head, 1.0}, {"top", BoundaryKind::head, 0.0}};
  return p;
}

// Fracture permeability per strip; every element of a strip varies around it by ±`spread`
// (a fixed pattern scaled by `phase`), as apertures do from pass to pass.
std::vector<double> permeability(const std::vector<double>& strip_k, double spread, double phase) {
  const Layer& l = layer();
  std::vector<double> k(l.mesh.triangles.size(), 1e-14);
  for (std::size_t t = 0; t < k.size(); ++t)
    if (l.fracture[t] >= 0) k[t] = strip_k[l.fracture[t]] * (1.0 + spread * std::sin(0.37 * t + phase));
  return k;
}

std::vector<PermeabilityTensor> isotropic(const std::vector<double>& k) {
  std::vector<PermeabilityTensor> out;
  for (double v : k) out.push_back({v, 0.0, v});
  return out;
}

double largest_head_difference(const FlowSolution& a, const FlowSolution& b) {
  double d = 0.0;
  for (std::size_t v = 0; v < a.head.size(); ++v) d = std::max(d, std::abs(a.head[v] - b.head[v]));
  return d;
}

// `round_off_floor`: where flow enters and leaves by one boundary, CG's answer from the true
// residual is kept at the heads' round-off, up to twice the exact solve's balance; elsewhere
// (the strips along the axes) at kBalanceTolerance.
void expect_same_solution(const FlowSolution& reused, const FlowSolution& exact, bool round_off_floor = false) {
  EXPECT_LE(largest_head_difference(reused, exact), kHeadAgreement);
  EXPECT_LE(reused.balance_error, kBalance);
  if (!reused.factorised) {
    EXPECT_LE(reused.balance_error,
              round_off_floor ? std::max(DarcySolver::kBalanceTolerance, 2.0 * exact.balance_error)
                              : DarcySolver::kBalanceTolerance);
  }
  const double inflow = exact.boundary_flow("bottom");
  EXPECT_NEAR(reused.boundary_flow("bottom"), inflow, 1e-9 * std::abs(inflow));
}

TEST(FactorReuse, TheFirstSolveFactorsAndIsTheExactOne) {
  const Layer& l = layer();
  DarcySolver reusing(l.mesh, bottom_to_top()), exact(l.mesh, bottom_to_top());
  const auto k = permeability({1e-9, 2e-9, 1e-9, 3e-9, 1e-9}, 0.0, 0.0);
  EXPECT_TRUE(reusing.kept_factor_permeability().empty());
  const FlowSolution a = reusing.solve_reusing_factor(k, {});
  const FlowSolution b = exact.solve(k);
  EXPECT_TRUE(a.factorised);
  EXPECT_EQ(a.cg_iterations, 0);
  EXPECT_EQ(a.head, b.head);  // the same code path, bit for bit
  EXPECT_EQ(reusing.kept_factor_permeability(), isotropic(k));
}

TEST(FactorReuse, SmallChangesSolveOnTheKeptFactorToTheExactHeads) {
  // Ten passes whose fracture permeabilities wander by up to ±2% about their strip's value
  // (up to 4% from one pass to another): every pass after the first runs CG on a kept factor,
  // which drifts from the matrix pass by pass until a solve takes more than kRefactorAfter
  // iterations; the pass after that one factors afresh.
  const Layer& l = layer();
  DarcySolver reusing(l.mesh, bottom_to_top()), exact(l.mesh, bottom_to_top());
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  FlowSolution last;
  int on_kept_factor = 0;
  bool refactor_due = true;  // no factor yet
  for (int pass = 0; pass < 10; ++pass) {
    const auto k = permeability(strips, 0.02, 0.3 * pass);
    const FlowSolution a = reusing.solve_reusing_factor(k, last.head);
    expect_same_solution(a, exact.solve(k));
    EXPECT_EQ(a.factorised, refactor_due) << "pass " << pass;
    if (!a.factorised) {
      ++on_kept_factor;
      EXPECT_LE(a.cg_iterations, DarcySolver::kMaxIterations) << "pass " << pass;
    }
    refactor_due = a.factorised ? false : a.cg_iterations > DarcySolver::kRefactorAfter;
    EXPECT_EQ(reusing.kept_factor_permeability().empty(), refactor_due) << "pass " << pass;
    last = a;
  }
  EXPECT_GE(on_kept_factor, 7);
}

TEST(FactorReuse, AFractureThatOpensIsSolvedWithinTheBoundOrFactoredAfresh) {
  // Contrast 1e5: one strip closed to the matrix's permeability (1e-14 m²), then opened to
  // 1e-9 m², then another closed, and so on; the old factor misses each change by 1e5. CG
  // either gets there within kMaxIterations or the matrix is factored afresh; the heads are
  // the exact ones either way.
  const Layer& l = layer();
  DarcySolver reusing(l.mesh, bottom_to_top()), exact(l.mesh, bottom_to_top());
  std::vector<double> strips{1e-9, 1e-14, 1e-9, 1e-9, 1e-9};
  FlowSolution last;
  int factorised = 0;
  for (int pass = 0; pass < 8; ++pass) {
    if (pass > 0) std::swap(strips[pass % 5], strips[(pass + 1) % 5]);
    const auto k = permeability(strips, 0.01, pass);
    const FlowSolution a = reusing.solve_reusing_factor(k, last.head);
    expect_same_solution(a, exact.solve(k));
    EXPECT_LE(a.cg_iterations, DarcySolver::kMaxIterations);
    factorised += a.factorised;
    last = a;
  }
  EXPECT_GE(factorised, 2);  // the first solve, and at least one jump the old factor could not follow
}

// Where a few elements jump (a stretch of a fracture closing, then opening again, by 1e5) and
// the rest barely move (±0.1%), the jump goes into the preconditioner exactly, as a low-rank
// correction of the kept factor (kMaxCorrectedElements), instead of a fresh factorisation.
// A pass without a correction keeps the factor in single precision, and a factor kept so is
// corrected where elements open (an update), not where they close (a downdate): the closed
// stretch keeps 1e-5 of its conductance, not much above the factor's rounding there. So, with
// the patch closed in odd passes and the factor first made with it open:
//   pass 1: closes, a downdate of the double factor: corrected;
//   pass 2: opens, as in the factor: nothing to correct, the factor goes to single precision;
//   pass 3: closes, a downdate of the single-precision factor: factored afresh (patch closed);
//   pass 4: opens, an update of that double factor: corrected;
//   pass 5: closes, as in the factor: single precision;
//   pass 6: opens, an update of the single-precision factor: corrected.
bool in_patch(int t) {
  const geometry::Point c = mesh::triangle_centroid(layer().mesh, t);
  return layer().fracture[t] == 1 && c.x > 0.4 && c.x < 0.45;
}

TEST(FactorReuse, AFewElementsThatJumpAreCorrectedNotFactoredAfresh) {
  const Layer& l = layer();
  DarcySolver reusing(l.mesh, bottom_to_top()), exact(l.mesh, bottom_to_top());
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  int patch = 0;
  for (int t = 0; t < l.mesh.triangle_count(); ++t) patch += in_patch(t);
  ASSERT_GT(patch, 20);
  ASSERT_LT(patch, 80);  // few enough that a correction costs less than a fresh factor (80: one iteration)
  FlowSolution last = reusing.solve_reusing_factor(permeability(strips, 0.001, 0.0), {});
  const bool factored_afresh[] = {false, false, true, false, false, false};
  const bool corrected[] = {true, false, false, true, false, true};
  for (int pass = 1; pass <= 6; ++pass) {
    auto k = permeability(strips, 0.001, 0.3 * pass);
    if (pass % 2 == 1)
      for (int t = 0; t < l.mesh.triangle_count(); ++t)
        if (in_patch(t)) k[t] = 1e-14;
    const FlowSolution a = reusing.solve_reusing_factor(k, last.head);
    expect_same_solution(a, exact.solve(k));
    EXPECT_EQ(a.factorised, factored_afresh[pass - 1]) << "pass " << pass;
    EXPECT_EQ(a.corrected_elements, corrected[pass - 1] ? patch : 0) << "pass " << pass;
    EXPECT_LE(a.cg_iterations, DarcySolver::kRefactorAfter) << "pass " << pass;
    last = a;
  }
}

// What a resumed run does: a new solver restores the factor the old one kept (of k0), and the
// next solve (of k1) from the same heads gives the same heads, bit for bit.
template <class Permeability>
void expect_restored_factor_gives_the_same_solution(const Permeability& k0, const Permeability& k1) {
  const Layer& l = layer();
  DarcySolver running(l.mesh, bottom_to_top());
  const FlowSolution first = running.solve_reusing_factor(k0, {});
  DarcySolver resumed(l.mesh, bottom_to_top());
  resumed.restore_kept_factor(running.kept_factor_permeability());
  const FlowSolution a = running.solve_reusing_factor(k1, first.head);
  const FlowSolution b = resumed.solve_reusing_factor(k1, first.head);
  EXPECT_FALSE(a.factorised);
  EXPECT_EQ(a.cg_iterations, b.cg_iterations);
  ASSERT_EQ(a.head.size(), b.head.size());
  EXPECT_EQ(std::memcmp(a.head.data(), b.head.data(), a.head.size() * sizeof(double)), 0);
  EXPECT_EQ(running.kept_factor_permeability(), resumed.kept_factor_permeability());
}

TEST(FactorReuse, ARestoredFactorGivesTheSameSolutionBitForBit) {
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  expect_restored_factor_gives_the_same_solution(permeability(strips, 0.02, 0.0), permeability(strips, 0.02, 1.0));
}

// The precision the factor is held in is part of what a resumed run restores: after a pass on
// the kept factor (which goes to single precision), a stretch that closes is factored afresh,
// not corrected (a downdate of a single-precision factor), in the running and the resumed
// solver alike, to the same heads bit for bit.
TEST(FactorReuse, ARestoredSinglePrecisionFactorTakesTheSamePath) {
  const Layer& l = layer();
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  DarcySolver running(l.mesh, bottom_to_top());
  running.solve_reusing_factor(permeability(strips, 0.001, 0.0), {});
  const FlowSolution second = running.solve_reusing_factor(permeability(strips, 0.001, 0.3), {});
  ASSERT_FALSE(second.factorised);
  ASSERT_TRUE(running.kept_factor_in_single_precision());
  DarcySolver resumed(l.mesh, bottom_to_top());
  resumed.restore_kept_factor(running.kept_factor_permeability(), running.kept_factor_in_single_precision());
  EXPECT_TRUE(resumed.kept_factor_in_single_precision());

  auto closed = permeability(strips, 0.001, 0.6);
  for (int t = 0; t < l.mesh.triangle_count(); ++t)
    if (in_patch(t)) closed[t] = 1e-14;
  const FlowSolution a = running.solve_reusing_factor(closed, second.head);
  const FlowSolution b = resumed.solve_reusing_factor(closed, second.head);
  EXPECT_TRUE(a.factorised);
  EXPECT_EQ(a.factorised, b.factorised);
  EXPECT_EQ(a.corrected_elements, b.corrected_elements);
  ASSERT_EQ(a.head.size(), b.head.size());
  EXPECT_EQ(std::memcmp(a.head.data(), b.head.data(), a.head.size() * sizeof(double)), 0);
}

// Joints make the permeability a tensor per element (matrix k_m plus a³/12 L/A t⊗t along a
// joint trace t): the strips of `layer()` as joints at 30° to their own direction would be
// unphysical, so each fracture element gets k_m I plus a rank-one part along a direction turned
// by `angle` from the strip's, its size wandering by ±`spread` as joint apertures do.
std::vector<PermeabilityTensor> joint_tensors(const std::vector<double>& strip_k, double spread, double phase,
                                              double angle) {
  const Layer& l = layer();
  std::vector<PermeabilityTensor> k(l.mesh.triangles.size(), {1e-14, 0.0, 1e-14});
  for (std::size_t t = 0; t < k.size(); ++t) {
    const int s = l.fracture[t];
    if (s < 0) continue;
    const double along = (s < 3 ? 0.0 : 0.5 * M_PI) + angle;  // the strip's direction, turned
    const double c = std::cos(along), n = std::sin(along);
    const double j = strip_k[s] * (1.0 + spread * std::sin(0.37 * t + phase));
    k[t] = {1e-14 + j * c * c, j * c * n, 1e-14 + j * n * n};
  }
  return k;
}

TEST(FactorReuse, BoundOfAUniformScalingIsItsChebyshevTerm) {
  // Every element's permeability scaled by f = 1.02, whether isotropic, axis-aligned or a
  // turned joint tensor: the pencil's eigenvalues are f for every element, so no element lies
  // outside c = 1.03, and the bound is the Chebyshev term of c = 1.03 alone,
  // ceil(log(ε/2) / log((c − 1)/(c + 1))) = ceil(−30.63 / −4.215) = 8 with ε = 1e-13; the
  // smaller rungs of the ladder (c ≤ 1.01) have every element outside.
  const Layer& l = layer();
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  const auto scaled = [](std::vector<PermeabilityTensor> k, double fx, double fy) {
    for (PermeabilityTensor& t : k) t = {t.xx * fx, t.xy * std::sqrt(fx * fy), t.yy * fy};
    return k;
  };
  for (const auto& k0 : {isotropic(permeability(strips, 0.0, 0.0)), joint_tensors(strips, 0.0, 0.0, 0.3)}) {
    DarcySolver solver(l.mesh, bottom_to_top());
    solver.solve(k0);
    EXPECT_EQ(solver.bound_iterations(scaled(k0, 1.02, 1.02)), 8);
    EXPECT_EQ(solver.bound_iterations(scaled(k0, 1.0 / 1.02, 1.0 / 1.02)), 8);
  }
  // Axis-aligned: xx up by 1.02, yy down by 1.02 (xy = 0 throughout): λ = 1.02 and 1/1.02.
  DarcySolver solver(l.mesh, bottom_to_top());
  const auto k0 = isotropic(permeability(strips, 0.0, 0.0));
  solver.solve(k0);
  EXPECT_EQ(solver.bound_iterations(scaled(k0, 1.02, 1.0 / 1.02)), 8);
}

TEST(FactorReuse, BoundSeesATurnedTensorOfTheSameSize) {
  // A tensor turned without being scaled has the same principal values, but it is not the
  // same matrix: a joint element's k = k_m I + j t⊗t turned by 90° has the pencil's
  // eigenvalues (k_m + j)/k_m and k_m/(k_m + j), so every such element lies outside every
  // spread of the ladder below 10 and the bound is at least 2 × their count.
  const Layer& l = layer();
  DarcySolver solver(l.mesh, bottom_to_top());
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  solver.solve(joint_tensors(strips, 0.0, 0.0, 0.0));
  // The kept matrix itself: every λ = 1, the Chebyshev term of c = 1.001, ceil(4.03) = 5.
  EXPECT_EQ(solver.bound_iterations(joint_tensors(strips, 0.0, 0.0, 0.0)), 5);
  const long strip_elements = std::count_if(l.fracture.begin(), l.fracture.end(), [](int s) { return s >= 0; });
  EXPECT_GE(solver.bound_iterations(joint_tensors(strips, 0.0, 0.0, 0.5 * M_PI)),
            std::min<long>(2 * strip_elements, std::numeric_limits<int>::max()));
}

TEST(FactorReuse, JointTensorsSolveOnTheKeptFactorToTheExactHeads) {
  // As SmallChangesSolveOnTheKeptFactorToTheExactHeads, with tensors along directions turned
  // 30° from the strips (off the mesh's axes, so every xy term is in play): from the second
  // pass on, CG on the kept factor, to the exact solve's heads and mass balance.
  const Layer& l = layer();
  DarcySolver reusing(l.mesh, bottom_to_top()), exact(l.mesh, bottom_to_top());
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  const double angle = M_PI / 6.0;
  FlowSolution last;
  int on_kept_factor = 0;
  for (int pass = 0; pass < 6; ++pass) {
    const auto k = joint_tensors(strips, 0.01, 0.3 * pass, angle);
    const FlowSolution a = reusing.solve_reusing_factor(k, last.head);
    expect_same_solution(a, exact.solve(k), /*round_off_floor=*/true);
    EXPECT_EQ(a.factorised, pass == 0 || last.cg_iterations > DarcySolver::kRefactorAfter) << "pass " << pass;
    if (!a.factorised) {
      ++on_kept_factor;
      EXPECT_LE(a.cg_iterations, DarcySolver::kMaxIterations) << "pass " << pass;
    }
    last = a;
  }
  EXPECT_GE(on_kept_factor, 4);
}

TEST(FactorReuse, AJointStretchThatTurnsIsCorrectedNotFactoredAfresh) {
  // As AFewElementsThatJumpAreCorrectedNotFactoredAfresh with joint tensors: a stretch of one
  // joint turns by 60° (the change of its tensors has both signs and every xy term), and grows
  // a hundredfold.
  const Layer& l = layer();
  DarcySolver reusing(l.mesh, bottom_to_top()), exact(l.mesh, bottom_to_top());
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  const FlowSolution first = reusing.solve_reusing_factor(joint_tensors(strips, 0.001, 0.0, M_PI / 6.0), {});
  auto k = joint_tensors(strips, 0.001, 0.3, M_PI / 6.0);
  const auto turned = joint_tensors({1e-9, 2e-7, 1e-9, 3e-9, 1e-9}, 0.001, 0.3, M_PI / 2.0);
  int patch = 0;
  for (int t = 0; t < l.mesh.triangle_count(); ++t)
    if (in_patch(t)) {
      k[t] = turned[t];
      ++patch;
    }
  const FlowSolution a = reusing.solve_reusing_factor(k, first.head);
  expect_same_solution(a, exact.solve(k), /*round_off_floor=*/true);
  EXPECT_FALSE(a.factorised);
  EXPECT_EQ(a.corrected_elements, patch);
  EXPECT_LE(a.cg_iterations, DarcySolver::kRefactorAfter);
}

TEST(FactorReuse, ARestoredTensorFactorGivesTheSameSolutionBitForBit) {
  const std::vector<double> strips{1e-9, 2e-9, 1e-9, 3e-9, 1e-9};
  expect_restored_factor_gives_the_same_solution(joint_tensors(strips, 0.01, 0.0, 0.3),
                                                 joint_tensors(strips, 0.01, 1.0, 0.3));
}

}  // namespace
}  // namespace hydrodda::hydro
