// Equivalent porosity and local apertures: elements per second against (elements, blocks).
//   build/bin/bench_porosity
//   build/bin/bench_porosity --benchmark_filter=Seal        # the seal of issue-scale runs
//   benchmarks/clip_side_by_side.sh build PEER_DIR          # BM_PeerBricks beside the peer
// BM_Porosity: a unit square meshed as n × n cells (2 n² triangles), covered by m × m square
// blocks shrunk to leave 1% apertures: every element clipped against the blocks over it.
// BM_Seal*: the fractured seal of benchmarks/seal_scenario.py (100 m × 20 m, C near-vertical
// joints and B flat beds, 2 mm apertures) over a structured mesh of the same element size, for
// the porosity mapping, the local apertures and the two together (the coupling loop's phase),
// and the fluid pressure's loads along the blocks' faces (a linear field, faces taking all of it).
// BM_PeerBricks: the triangles and rotated bricks of shared/peers/clip's clipbench, built the
// same way from the same seed, so that both map identical inputs.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "coupling/local_aperture.hpp"
#include "coupling/porosity.hpp"
#include "coupling/pressure_forces.hpp"
#include "geometry/domain_cutting.hpp"

namespace {

using hydrodda::geometry::Point;
using hydrodda::geometry::Polygon;

struct Case {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Polygon> blocks;
  Polygon domain;
};

// nx × ny cells over [x0, x1] × [y0, y1], two counter-clockwise triangles a cell (a, b, c and
// a, c, d: the diagonal from the lower left corner, as the peer's mesh).
void add_structured_mesh(Case& c, double x1, double y1, int nx, int ny) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) c.nodes.push_back({x1 * i / nx, y1 * j / ny});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, d = a + nx + 1, e = d + 1;
      c.triangles.push_back({a, b, e});
      c.triangles.push_back({a, e, d});
    }
}

Case make_case(int n, int m) {
  Case c;
  add_structured_mesh(c, 1.0, 1.0, n, n);
  const double size = 1.0 / m, gap = 0.005 * size;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double x0 = i * size + gap, y0 = j * size + gap, x1 = (i + 1) * size - gap, y1 = (j + 1) * size - gap;
      c.blocks.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    }
  return c;
}

// The seal: joints tilted by up to 1° and beds undulating by up to 2 cm (deterministic, from
// a fixed sequence), cut and shrunk as the program does for a scenario's geometry.
Case make_seal(int columns, int beds, double element_size) {
  constexpr double kWidth = 100.0, kHeight = 20.0, kAperture = 0.002;
  Case c;
  c.domain = {{0, 0}, {kWidth, 0}, {kWidth, kHeight}, {0, kHeight}};
  std::mt19937_64 rng(2006);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<hydrodda::geometry::Segment2> fractures;
  const double slope = std::tan(std::numbers::pi / 180.0);
  for (int k = 1; k <= columns; ++k) {
    const double x = kWidth * k / (columns + 1), shift = kHeight * slope * unit(rng) / 2;
    fractures.push_back({{x - shift, 0.0}, {x + shift, kHeight}});
  }
  for (int k = 1; k <= beds; ++k) {
    const double y = kHeight * k / (beds + 1);
    fractures.push_back({{0.0, y + 0.02 * unit(rng)}, {kWidth, y + 0.02 * unit(rng)}});
  }
  const auto cut = hydrodda::geometry::cut_domain(c.domain, fractures, {});
  c.blocks = hydrodda::geometry::shrink_blocks(cut.blocks, c.domain, kAperture);
  // Right triangles of legs h: the structured mesh with the program's element size h.
  add_structured_mesh(c, kWidth, kHeight, static_cast<int>(std::lround(kWidth / element_size)),
                      static_cast<int>(std::lround(kHeight / element_size)));
  return c;
}

std::vector<Point> centroids_of(const Case& c) {
  std::vector<Point> out;
  for (const auto& t : c.triangles) out.push_back((c.nodes[t[0]] + c.nodes[t[1]] + c.nodes[t[2]]) / 3.0);
  return out;
}

void set_counters(benchmark::State& state, const Case& c) {
  state.counters["elements"] = static_cast<double>(c.triangles.size());
  state.counters["blocks"] = static_cast<double>(c.blocks.size());
  state.counters["elements_per_second"] =
      benchmark::Counter(static_cast<double>(c.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Porosity(benchmark::State& state) {
  const Case c = make_case(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const hydrodda::coupling::PorosityMapper mapper(c.nodes, c.triangles);
  for (auto _ : state) {
    auto field = mapper.compute(c.blocks, 0.1);
    benchmark::DoNotOptimize(field.porosity.data());
  }
  set_counters(state, c);
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

// (columns, beds, element size in mm): (100, 99, 62.5) is the seal of 10,100 blocks over
// 1,024,000 triangles; (40, 24, 160) that of run_seal.sh's default, 1,025 over 156,250.
const Case& seal(const benchmark::State& state) {
  static std::vector<std::pair<std::array<long, 3>, Case>> cache;
  const std::array<long, 3> key{state.range(0), state.range(1), state.range(2)};
  for (const auto& [k, c] : cache)
    if (k == key) return c;
  cache.emplace_back(key, make_seal(static_cast<int>(key[0]), static_cast<int>(key[1]), key[2] * 1e-3));
  return cache.back().second;
}

void BM_SealPorosity(benchmark::State& state) {
  const Case& c = seal(state);
  const hydrodda::coupling::PorosityMapper mapper(c.nodes, c.triangles);
  for (auto _ : state) {
    auto field = mapper.compute(c.blocks, 0.1);
    benchmark::DoNotOptimize(field.porosity.data());
  }
  set_counters(state, c);
}

// The same with the block ∩ element pieces the seepage force needs (a coupled run with a
// block of biot_coefficient > 0): every block over an element is clipped, without early outs.
void BM_SealPorosityWithPieces(benchmark::State& state) {
  const Case& c = seal(state);
  const hydrodda::coupling::PorosityMapper mapper(c.nodes, c.triangles);
  hydrodda::coupling::BlockPieces pieces;
  for (auto _ : state) {
    auto field = mapper.compute(c.blocks, 0.1, &pieces);
    benchmark::DoNotOptimize(field.porosity.data());
    benchmark::DoNotOptimize(pieces.size());
  }
  set_counters(state, c);
}

void BM_SealApertures(benchmark::State& state) {
  const Case& c = seal(state);
  const hydrodda::coupling::PorosityMapper mapper(c.nodes, c.triangles);
  const auto field = mapper.compute(c.blocks, 0.1);
  const std::vector<Point> centroids = centroids_of(c);
  long open = 0;  // the elements with open area, whose apertures are sought
  for (double a : field.fracture_area) open += a > 0.0;
  for (auto _ : state) {
    auto apertures = hydrodda::coupling::compute_local_apertures(centroids, field.fracture_area, c.blocks, c.domain,
                                                                 state.range(2) * 1e-3);
    benchmark::DoNotOptimize(apertures.data());
  }
  set_counters(state, c);
  state.counters["open_elements"] = static_cast<double>(open);
}

// The loop's phase: the porosity, then the apertures of the elements with open area.
void BM_SealPorosityAndApertures(benchmark::State& state) {
  const Case& c = seal(state);
  const hydrodda::coupling::PorosityMapper mapper(c.nodes, c.triangles);
  const std::vector<Point> centroids = centroids_of(c);
  for (auto _ : state) {
    auto field = mapper.compute(c.blocks, 0.1);
    auto apertures = hydrodda::coupling::compute_local_apertures(centroids, field.fracture_area, c.blocks, c.domain,
                                                                 state.range(2) * 1e-3);
    benchmark::DoNotOptimize(apertures.data());
  }
  set_counters(state, c);
}

// The face loads of a pass (coupling::FacePressureLoads): every face of every block
// integrated through the elements it crosses, the pressure ρ g (50 m − y) at the nodes.
void BM_SealFaceLoads(benchmark::State& state) {
  const Case& c = seal(state);
  hydrodda::mesh::TriangleMesh mesh;
  mesh.nodes = c.nodes;
  mesh.triangles = c.triangles;
  const hydrodda::coupling::FacePressureLoads loads(mesh);
  std::vector<double> pressure;
  for (Point p : mesh.nodes) pressure.push_back(9810.0 * (50.0 - p.y));
  const std::vector<double> biot(c.blocks.size(), 0.0);
  long faces = 0;
  for (const Polygon& block : c.blocks) faces += static_cast<long>(block.size());
  for (auto _ : state) {
    auto forces = loads.compute(c.blocks, pressure, biot);
    benchmark::DoNotOptimize(forces.data());
  }
  set_counters(state, c);
  state.counters["faces"] = static_cast<double>(faces);
}

BENCHMARK(BM_SealPorosity)->Args({40, 24, 160})->Args({100, 99, 62})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SealPorosityWithPieces)->Args({40, 24, 160})->Args({100, 99, 62})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SealApertures)->Args({40, 24, 160})->Args({100, 99, 62})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SealPorosityAndApertures)->Args({40, 24, 160})->Args({100, 99, 62})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SealFaceLoads)->Args({40, 24, 160})->Args({100, 99, 62})->Unit(benchmark::kMillisecond);

// clipbench's inputs (shared/peers/clip/clipbench.cpp, "T B" on its command line): a square of
// side L = 2 h nx meshed as n × n cells, and a staggered pattern of 2:1 bricks of height h
// (nx a row, half bricks at the ends of odd rows, 2 nx rows), each shrunk by `gap` and turned
// by U(−2°, 2°) about its centroid, drawn from mt19937_64 with seed 1 in the same order.
Case make_peer_bricks(int n, int nx) {
  constexpr double kHeight = 0.05, kGap = 0.002, kRotation = 2.0;
  const double w = 2 * kHeight, side = nx * w;
  Case c;
  add_structured_mesh(c, side, side, n, n);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> angle(-kRotation * std::numbers::pi / 180, kRotation * std::numbers::pi / 180);
  for (int r = 0; r < 2 * nx; ++r) {
    std::vector<double> cut{0};
    for (double x = (r % 2 ? w / 2 : w); x < side - 1e-9 * side; x += w) cut.push_back(x);
    cut.push_back(side);
    for (std::size_t k = 0; k + 1 < cut.size(); ++k) {
      const double x0 = cut[k] + kGap, x1 = cut[k + 1] - kGap, y0 = r * kHeight + kGap, y1 = (r + 1) * kHeight - kGap;
      const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), th = angle(rng), cs = std::cos(th), sn = std::sin(th);
      Polygon brick{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
      for (Point& p : brick) {
        const double dx = p.x - cx, dy = p.y - cy;
        p = {cx + cs * dx - sn * dy, cy + sn * dx + cs * dy};
        // The peer clips each brick to the square, a no-op for these sizes: checked here.
        if (p.x < 0 || p.y < 0 || p.x > side || p.y > side) throw std::logic_error("a brick leaves the square");
      }
      c.blocks.push_back(std::move(brick));
    }
  }
  return c;
}

// (T, B) as clipbench takes them: n = round(√(T/2)), nx = round((√(1 + 8B) − 1)/4).
void BM_PeerBricks(benchmark::State& state) {
  const double t = static_cast<double>(state.range(0)), b = static_cast<double>(state.range(1));
  const Case c = make_peer_bricks(static_cast<int>(std::lround(std::sqrt(t / 2))),
                                  static_cast<int>(std::lround((std::sqrt(1 + 8 * b) - 1) / 4)));
  const hydrodda::coupling::PorosityMapper mapper(c.nodes, c.triangles);
  hydrodda::coupling::PorosityField field;
  for (auto _ : state) {
    field = mapper.compute(c.blocks, 0.0);
    benchmark::DoNotOptimize(field.porosity.data());
  }
  // The porosity clipbench prints: 1 − Σ covered / L² (with no matrix porosity, A_f = A_e − covered).
  double open = 0.0, total = 0.0;
  for (std::size_t e = 0; e < field.fracture_area.size(); ++e) {
    open += field.fracture_area[e];
    total += mapper.element_areas()[e];
  }
  set_counters(state, c);
  state.counters["porosity"] = open / total;
}

BENCHMARK(BM_PeerBricks)->Args({100000, 1000})->Args({1000000, 10000})->Args({4000000, 10000})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
