// Point location speed: points located per second in a Gmsh mesh refined along lines.
//   build/bin/bench_mesh
#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <vector>

#include "mesh/mesh_request.hpp"
#include "mesh/point_locator.hpp"

namespace {

using namespace hydrodda;

const mesh::TriangleMesh& get_mesh(long size_um) {
  static std::map<long, mesh::TriangleMesh> cache;
  auto it = cache.find(size_um);
  if (it == cache.end()) {
    mesh::MeshRequest r;
    r.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    r.size = size_um * 1e-6;
    r.fracture_size = r.size / 8;
    r.refine_distance = 3.5 * r.size;
    r.refinement_lines = {{{0, 0.25}, {1, 0.3}}, {{0.2, 0}, {0.7, 1}}};
    it = cache.emplace(size_um, mesh::generate_mesh(r)).first;
  }
  return it->second;
}

void BM_BuildLocator(benchmark::State& state) {
  const auto& m = get_mesh(state.range(0));
  for (auto _ : state) {
    mesh::PointLocator locator(m);
    benchmark::DoNotOptimize(&locator);
  }
  state.counters["triangles"] = m.triangle_count();
}

void BM_Locate(benchmark::State& state) {
  const auto& m = get_mesh(state.range(0));
  const mesh::PointLocator locator(m);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<geometry::Point> points(1 << 16);
  for (auto& p : points) p = {u(rng), u(rng)};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locator.locate(points[i]));
    i = (i + 1) & (points.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["triangles"] = m.triangle_count();
}

BENCHMARK(BM_BuildLocator)->Arg(20000)->Arg(6000)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Locate)->Arg(20000)->Arg(6000)->Arg(2000);

}  // namespace

BENCHMARK_MAIN();
