// The block Cholesky factorisation (dda/block_cholesky.hpp) against CHOLMOD's on the same
// matrix and the same elimination order: the wall's block graph (tests/dda/test_models.hpp),
// ordered by the block minimum degree the program uses, each block's six unknowns eliminated
// together. CHOLMOD's analysis is made once, outside the timing; each iteration is one
// numeric factorisation. Argument 1: 0 simplicial LLᵀ, 1 supernodal (dense BLAS on each
// supernode: OpenBLAS through the system's libblas). Counter: the factor's nonzeros, the same
// for all (docs/studies/2026-11-29-wall-whole-program-profile.md).
//
//   build/bin/bench_block_factor --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <cholmod.h>

#include <benchmark/benchmark.h>

#include "dda/block_cholesky.hpp"
#include "dda/test_models.hpp"

namespace {

using hydrodda::dda::BlockMatrix;

// Argument 1: the block kernels, 0 portable, 1 vectorised (AVX2 and FMA; skipped where the
// CPU lacks them).
bool choose_kernels(benchmark::State& state) {
  const bool vectorised = state.range(1) == 1;
  if (hydrodda::dda::BlockCholesky::use_vectorised_kernels(vectorised) == vectorised) return true;
  state.SkipWithError("this CPU lacks AVX2 or FMA");
  return false;
}

void BM_WallGraphBlockFactor(benchmark::State& state) {
  if (!choose_kernels(state)) return;
  const BlockMatrix a = hydrodda::dda::testing::make_wall_graph_matrix(static_cast<int>(state.range(0)));
  const std::vector<int> order = hydrodda::dda::order_by_minimum_degree(a);
  hydrodda::dda::BlockCholesky factor;
  for (auto _ : state) benchmark::DoNotOptimize(factor.factorise(a, order));
  state.counters["L_nonzeros"] =
      36.0 * static_cast<double>(factor.off_diagonal_blocks()) + 21.0 * a.block_count;
  hydrodda::dda::BlockCholesky::use_vectorised_kernels(true);
}
BENCHMARK(BM_WallGraphBlockFactor)->ArgsProduct({{40, 100}, {0, 1}})->Unit(benchmark::kMillisecond);

// A forward and a backward sweep with the factor, as each CG iteration makes them.
void BM_WallGraphBlockSweeps(benchmark::State& state) {
  if (!choose_kernels(state)) return;
  const BlockMatrix a = hydrodda::dda::testing::make_wall_graph_matrix(static_cast<int>(state.range(0)));
  hydrodda::dda::BlockCholesky factor;
  factor.factorise(a, hydrodda::dda::order_by_minimum_degree(a));
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(a.size(), -1.0, 1.0);
  for (auto _ : state) {
    factor.solve_in_place(x);
    benchmark::DoNotOptimize(x.data());
  }
  hydrodda::dda::BlockCholesky::use_vectorised_kernels(true);
}
BENCHMARK(BM_WallGraphBlockSweeps)->ArgsProduct({{40, 100}, {0, 1}})->Unit(benchmark::kMicrosecond);

void BM_WallGraphCholmodFactor(benchmark::State& state) {
  const BlockMatrix a = hydrodda::dda::testing::make_wall_graph_matrix(static_cast<int>(state.range(0)));
  const std::vector<int> blocks = hydrodda::dda::order_by_minimum_degree(a);
  std::vector<int> order(6 * blocks.size());
  for (std::size_t k = 0; k < blocks.size(); ++k)
    for (int r = 0; r < 6; ++r) order[6 * k + r] = 6 * blocks[k] + r;
  const hydrodda::dda::SparseMatrix lower = a.lower_triangle();
  cholmod_sparse view{};
  view.nrow = view.ncol = lower.rows();
  view.nzmax = lower.nonZeros();
  view.p = const_cast<int*>(lower.outerIndexPtr());
  view.i = const_cast<int*>(lower.innerIndexPtr());
  view.x = const_cast<double*>(lower.valuePtr());
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_GIVEN;
  common.supernodal = state.range(1) == 1 ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  common.final_ll = true;
  common.print = 0;
  cholmod_factor* l = cholmod_analyze_p(&view, order.data(), nullptr, 0, &common);
  for (auto _ : state) {
    if (!cholmod_factorize(&view, l, &common)) state.SkipWithError("cholmod_factorize failed");
  }
  state.counters["L_nonzeros"] = common.lnz;
  cholmod_free_factor(&l, &common);
  cholmod_finish(&common);
}
BENCHMARK(BM_WallGraphCholmodFactor)
    ->Args({40, 0})
    ->Args({40, 1})
    ->Args({100, 0})
    ->Args({100, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
