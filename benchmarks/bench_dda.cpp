// Time per DDA step against block count: a staggered brick wall on a fixed base (the same
// wall the ntdda peer runs, see brickwall.py: 2 m × 1 m bricks, static, Δt 1e-3 s) and a
// random packing of irregular quadrilaterals settled on a fixed base. Each benchmark
// iteration is one step; 20 steps per case, as the peer driver times them.

#include <benchmark/benchmark.h>

#include "dda/block_cholesky.hpp"
#include "dda/contact_detection.hpp"
#include "dda/contact_search.hpp"
#include "dda/system.hpp"
#include "dda/test_models.hpp"  // tests/dda: the brick wall the tests and ntdda run

namespace {

using hydrodda::dda::BlockMatrix;
using hydrodda::dda::LinearSolver;
using hydrodda::dda::ModelDefinition;
using hydrodda::dda::Point;
using hydrodda::dda::System;

using hydrodda::dda::testing::make_brick_wall;
using hydrodda::dda::testing::make_random_packing;
using hydrodda::dda::testing::make_wall_graph_matrix;

void run_steps(benchmark::State& state, ModelDefinition model, int settle = 0,
               std::unique_ptr<LinearSolver> solver = hydrodda::dda::make_block_factor_solver()) {
  const int blocks = static_cast<int>(model.blocks.size());
  System system(std::move(model), std::move(solver));
  system.run_steps(settle);
  int iterations = 0;
  int contacts = 0;
  const auto before = system.solver_counts();
  for (auto _ : state) {
    const auto report = system.step();
    iterations += report.open_close_iterations;
    contacts = report.contacts;
  }
  state.counters["blocks"] = blocks;
  state.counters["contacts"] = contacts;
  state.counters["oc_iter"] = static_cast<double>(iterations) / state.iterations();
  const auto after = system.solver_counts();
  const auto per_step = [&](long count) { return static_cast<double>(count) / state.iterations(); };
  state.counters["factor"] = per_step(after.factorisations - before.factorisations);
  state.counters["solves"] = per_step(after.solves - before.solves);
  state.counters["estimates"] = per_step(after.estimates - before.estimates);
  state.counters["cg_iter"] = per_step(after.iterations - before.iterations);
  state.counters["updates"] = per_step(after.modified_terms - before.modified_terms);
}

void BM_BrickWall(benchmark::State& state) {
  run_steps(state, make_brick_wall(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
}
BENCHMARK(BM_BrickWall)
    ->Args({3, 3})
    ->Args({10, 10})
    ->Args({20, 20})
    ->Args({20, 40})
    ->Args({40, 40})
    ->Args({100, 100})
    ->Args({100, 1000})  // 100,001 blocks: the growth from 10^4
    ->Iterations(20)
    ->Unit(benchmark::kMillisecond);

// The same wall through CHOLMOD (simplicial LDLᵀ, rank-one updates): what the hand-written
// block factorisation must beat to earn its place.
void BM_BrickWallCholmod(benchmark::State& state) {
  run_steps(state, make_brick_wall(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))), 0,
            hydrodda::dda::make_cholmod_solver());
}
BENCHMARK(BM_BrickWallCholmod)->Args({20, 20})->Args({40, 40})->Iterations(20)->Unit(benchmark::kMillisecond);

// One factorisation and one solve from scratch, the block factor against CHOLMOD on the same
// matrix (argument 1: CHOLMOD).
void BM_WallGraphFactorAndSolve(benchmark::State& state) {
  const BlockMatrix a = make_wall_graph_matrix(static_cast<int>(state.range(0)));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.size(), -1.0, 1.0);
  for (auto _ : state) {
    auto solver = state.range(1) == 1 ? hydrodda::dda::make_cholmod_solver()
                                      : hydrodda::dda::make_block_factor_solver();
    solver->factor(a);
    benchmark::DoNotOptimize(solver->solve(b));
  }
  state.counters["blocks"] = a.block_count;
}
BENCHMARK(BM_WallGraphFactorAndSolve)
    ->Args({40, 0})
    ->Args({40, 1})
    ->Args({100, 0})
    ->Args({100, 1})
    ->Unit(benchmark::kMillisecond);

// The factor's work (blocks of L) in the two parts of its elimination tree that run side by
// side, and in the top that runs after them.
void add_part_counters(benchmark::State& state, const hydrodda::dda::BlockCholesky& factor) {
  const auto parts = factor.part_blocks();
  state.counters["part_0"] = static_cast<double>(parts[0]);
  state.counters["part_1"] = static_cast<double>(parts[1]);
  state.counters["top"] = static_cast<double>(parts[2]);
}

// The block factor's two halves apart on the wall's matrix: the factorisation, and one pair
// of triangular solves with the kept factor (the step's most frequent operation: one per CG
// iteration). Counter: L's off-diagonal 6×6 blocks, the fill.
void BM_WallGraphFactorise(benchmark::State& state) {
  const BlockMatrix a = make_wall_graph_matrix(static_cast<int>(state.range(0)));
  const std::vector<int> order = hydrodda::dda::order_by_minimum_degree(a);
  hydrodda::dda::BlockCholesky factor;
  for (auto _ : state) benchmark::DoNotOptimize(factor.factorise(a, order));
  state.counters["blocks"] = a.block_count;
  state.counters["L_blocks"] = static_cast<double>(factor.off_diagonal_blocks());
  add_part_counters(state, factor);
}
BENCHMARK(BM_WallGraphFactorise)->Arg(40)->Arg(100)->Unit(benchmark::kMillisecond);

// The minimum degree ordering of the wall's block graph (the first factorisation's).
void BM_WallGraphOrdering(benchmark::State& state) {
  const BlockMatrix a = make_wall_graph_matrix(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(hydrodda::dda::order_by_minimum_degree(a));
}
BENCHMARK(BM_WallGraphOrdering)->Arg(40)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_WallGraphTriangularSolves(benchmark::State& state) {
  const BlockMatrix a = make_wall_graph_matrix(static_cast<int>(state.range(0)));
  hydrodda::dda::BlockCholesky factor;
  factor.factorise(a, hydrodda::dda::order_by_minimum_degree(a));
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(a.size(), -1.0, 1.0);
  for (auto _ : state) {
    factor.solve_in_place(x);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["blocks"] = a.block_count;
  state.counters["L_blocks"] = static_cast<double>(factor.off_diagonal_blocks());
  add_part_counters(state, factor);
}
BENCHMARK(BM_WallGraphTriangularSolves)->Arg(40)->Arg(100)->Unit(benchmark::kMicrosecond);

// Contact detection alone on the wall as it stands (rows × rows blocks, the contact distance a
// step uses there: 2.5 × 1% of half the height): the broad phase, then the narrow phase over
// its pairs, one thread. Counters: the pairs and the candidate contacts.
void BM_WallContactDetection(benchmark::State& state) {
  const int rows = static_cast<int>(state.range(0));
  const ModelDefinition wall = make_brick_wall(rows, rows);
  std::vector<hydrodda::geometry::Box> boxes;
  std::vector<char> fixed;
  for (const auto& b : wall.blocks) {
    boxes.push_back(hydrodda::geometry::bounding_box(b.polygon));
    fixed.push_back(b.fixed);
  }
  const double distance = 2.5 * 0.01 * 0.5 * (rows + 1.0);
  std::size_t pair_count = 0, candidate_count = 0;
  for (auto _ : state) {
    const auto pairs = hydrodda::dda::find_block_pairs(boxes, distance, fixed);
    hydrodda::dda::ContactCandidates found;
    for (auto [a, b] : pairs)
      hydrodda::dda::find_pair_contacts(wall.blocks[a].polygon, a, wall.blocks[b].polygon, b, distance, found);
    benchmark::DoNotOptimize(found.data());
    pair_count = pairs.size();
    candidate_count = found.size();
  }
  state.counters["pairs"] = static_cast<double>(pair_count);
  state.counters["candidates"] = static_cast<double>(candidate_count);
}
BENCHMARK(BM_WallContactDetection)->Arg(40)->Unit(benchmark::kMicrosecond);

// The same wall through the contact search a step uses: argument 1 = 1, with the lists kept
// from the last search (a step whose blocks barely moved); 0, made afresh each time (the
// first step, or one after the blocks moved half the skin). Two threads where there are two.
void BM_WallContactSearch(benchmark::State& state) {
  const int rows = static_cast<int>(state.range(0));
  const ModelDefinition wall = make_brick_wall(rows, rows);
  std::vector<std::span<const Point>> polygons;
  std::vector<char> fixed;
  for (const auto& b : wall.blocks) {
    polygons.emplace_back(b.polygon);
    fixed.push_back(b.fixed);
  }
  const double distance = 2.5 * 0.01 * 0.5 * (rows + 1.0);
  hydrodda::dda::ContactSearch search(distance, 0.2 * distance);
  hydrodda::dda::ContactCandidates found;
  for (auto _ : state) {
    if (state.range(1) == 0) search.forget();
    search.find(polygons, fixed, found);
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["candidates"] = static_cast<double>(found.size());
  state.counters["lists"] = static_cast<double>(search.list_count());
}
BENCHMARK(BM_WallContactSearch)->Args({40, 0})->Args({40, 1})->Unit(benchmark::kMicrosecond);

// Rows × columns. A packing's state after its untimed steps depends on its height (a taller
// column is cut to shorter steps while its lower rows collide, and has more rows still
// falling free); packings of one height and growing width (40 × 40, 40 × 250) are at the
// same stage when timed, so their ratio is the growth of a step's cost with the block count
// alone.
void BM_RandomPacking(benchmark::State& state) {
  // 60 steps of 1 ms: a free fall of 18 mm, past every initial gap.
  run_steps(state, make_random_packing(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))), 60);
}
BENCHMARK(BM_RandomPacking)
    ->Args({3, 3})
    ->Args({10, 10})
    ->Args({20, 20})
    ->Args({40, 40})
    ->Args({100, 100})
    ->Args({40, 250})
    ->Iterations(20)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
