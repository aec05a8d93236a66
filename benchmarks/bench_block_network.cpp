// Cutting a seal into blocks along two joint sets: traces → blocks, slivers merged, aperture.
//   build/bin/bench_block_network
// A 100 m × 20 m seal crossed by a steep set (80° ± 5°, traces 8 spacings long) and a gentle
// one (10° ± 5°), both of spacing s ± 0.3 s, an aperture of 1 mm; s = 2, 1, 0.5, 0.3 m.

#include <benchmark/benchmark.h>

#include <vector>

#include "geometry/block_network.hpp"
#include "geometry/joint_sets.hpp"

namespace {

namespace g = hydrodda::geometry;

g::BlockNetworkRequest make_seal(double spacing) {
  g::BlockNetworkRequest request;
  request.domain = {{0, 0}, {100, 0}, {100, 20}, {0, 20}};
  request.aperture = 1e-3;
  for (int s = 0; s < 2; ++s) {
    g::JointSet set;
    set.angle = s == 0 ? 80.0 : 10.0;
    set.angle_spread = 5.0;
    set.spacing = spacing;
    set.spacing_spread = 0.3 * spacing;
    set.length = 8 * spacing;
    set.length_spread = 2 * spacing;
    set.region = request.domain;
    set.seed = 9 + static_cast<unsigned>(s);
    for (const g::Segment2& t : g::generate_joint_traces(set)) request.traces.push_back({t, {}});
  }
  return request;
}

void BM_CutSealIntoBlocks(benchmark::State& state) {
  const g::BlockNetworkRequest request = make_seal(static_cast<double>(state.range(0)) / 10.0);
  g::BlockNetwork network;
  for (auto _ : state) {
    network = g::build_block_network(request);
    benchmark::DoNotOptimize(network.blocks.data());
  }
  state.counters["traces"] = static_cast<double>(request.traces.size());
  state.counters["blocks"] = static_cast<double>(network.blocks.size());
  state.counters["merged"] = network.merged_small + network.merged_thin;
}
BENCHMARK(BM_CutSealIntoBlocks)->Arg(20)->Arg(10)->Arg(5)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
