// Equivalent-porosity mapping: elements per second against (elements, blocks).
//   build/bin/bench_porosity
// A unit square meshed as n × n cells (2 n² triangles), covered by m × m square blocks shrunk
// to leave 1% apertures: the case of the coupling loop, where every element is clipped against
// the blocks over it.

#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "coupling/porosity.hpp"

namespace {

using hydrodda::geometry::Point;
using hydrodda::geometry::Polygon;

struct Case {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Polygon> blocks;
};

Case make_case(int n, int m) {
  Case c;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) c.nodes.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, d = a + n + 1, e = d + 1;
      c.triangles.push_back({a, b, e});
      c.triangles.push_back({a, e, d});
    }
  const double size = 1.0 / m, gap = 0.005 * size;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double x0 = i * size + gap, y0 = j * size + gap, x1 = (i + 1) * size - gap, y1 = (j + 1) * size - gap;
      c.blocks.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    }
  return c;
}

void BM_Porosity(benchmark::State& state) {
  const Case c = make_case(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const hydrodda::coupling::PorosityMapper mapper(c.nodes, c.triangles);
  for (auto _ : state) {
    auto field = mapper.compute(c.blocks, 0.1);
    benchmark::DoNotOptimize(field.porosity.data());
  }
  state.counters["elements"] = static_cast<double>(c.triangles.size());
  state.counters["blocks"] = static_cast<double>(c.blocks.size());
  state.counters["elements_per_second"] =
      benchmark::Counter(static_cast<double>(c.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}

// (n, m): 2n² elements, m² blocks, from (2e4, 100) to (1.28e6, 10,000).
BENCHMARK(BM_Porosity)
    ->Args({100, 10})
    ->Args({316, 32})
    ->Args({316, 100})
    ->Args({707, 100})
    ->Args({800, 100})
    ->Args({800, 32})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
