// Flow model speed: mesh generation, set-up (pattern + symbolic analysis), and the per-
// iteration solve (re-assembly into the fixed pattern, numeric refactorisation, solve with
// iterative refinement, fluxes and boundary flows) on the "three fractures" problem: the unit
// square, h = 1 left, 0 right, three full-length strips of width 0.004 at y = 0.25, 0.5,
// 0.75 with k = 1e-9 m² in a matrix of 1e-15 m² (contrast 1e6).
//
//   build/bin/bench_hydro                         # our own meshes, 1e4 to 1e6 triangles
//   OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 build/bin/bench_hydro --benchmark_filter=LatePass
//                                                 # a late coupling pass, afresh or on the kept factor
//   HYDRODDA_PEER_MESH=case/mesh.msh build/bin/bench_hydro --benchmark_filter=PeerMesh
//                                                 # the peer benchmark's own mesh file
// Run with OMP_THREAD_LIMIT=1 OPENBLAS_NUM_THREADS=1 to compare with one-thread peers.
// HYDRODDA_ORDERING=automatic selects CHOLMOD's automatic (AMD) ordering instead of METIS.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "hydro/darcy_solver.hpp"
#include "mesh/mesh_request.hpp"

namespace {

using namespace hydrodda;

constexpr double kMatrixK = 1e-15, kStripK = 1e-9, kStripWidth = 0.004;

// The far-field size in micrometres is the benchmark argument; the strips are meshed at
// size/8, growing back over 3.5 × size (the peer's grading of 0.25).
mesh::MeshRequest make_three_fractures(double size) {
  mesh::MeshRequest r;
  r.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  r.size = size;
  r.fracture_size = size / 8;
  r.refine_distance = kStripWidth / 2 + (size - size / 8) / 0.25;
  for (double y : {0.25, 0.5, 0.75}) {
    r.refinement_lines.push_back({{0, y}, {1, y}});
    r.regions.push_back({"strip", {{0, y - kStripWidth / 2}, {1, y - kStripWidth / 2},
                                   {1, y + kStripWidth / 2}, {0, y + kStripWidth / 2}}});
  }
  return r;
}

const mesh::TriangleMesh& get_mesh(long size_um) {
  static std::map<long, mesh::TriangleMesh> cache;
  auto it = cache.find(size_um);
  if (it == cache.end()) it = cache.emplace(size_um, mesh::generate_mesh(make_three_fractures(size_um * 1e-6))).first;
  return it->second;
}

hydro::DarcyProblem make_problem() {
  hydro::DarcyProblem p;
  p.boundaries = {{"left", hydro::BoundaryKind::head, 1.0}, {"right", hydro::BoundaryKind::head, 0.0}};
  return p;
}

std::vector<double> make_permeability(const mesh::TriangleMesh& m, double strip_k) {
  std::vector<double> k(m.triangles.size(), kMatrixK);
  for (int t = 0; t < m.triangle_count(); ++t) {
    const std::string& name = m.region_names[m.region[t]];
    if (name == "strip" || name == "f1" || name == "f2" || name == "f3") k[t] = strip_k;
  }
  return k;
}

std::unique_ptr<numerics::SparseCholesky> make_solver() {
  const char* ordering = std::getenv("HYDRODDA_ORDERING");
  return hydro::make_cholmod_solver(ordering && std::string(ordering) == "automatic"
                                        ? hydro::FillOrdering::automatic
                                        : hydro::FillOrdering::metis);
}

void set_mesh_counters(benchmark::State& state, const mesh::TriangleMesh& m) {
  state.counters["triangles"] = m.triangle_count();
  state.counters["nodes"] = m.node_count();
}

void BM_GenerateMesh(benchmark::State& state) {
  const auto request = make_three_fractures(state.range(0) * 1e-6);
  mesh::TriangleMesh m;
  for (auto _ : state) m = mesh::generate_mesh(request);
  set_mesh_counters(state, m);
}

// Gmsh's 2D algorithms on the same request (about 1e5 triangles): 1 MeshAdapt, 5 Delaunay,
// 6 Frontal-Delaunay.
void BM_GenerateMeshAlgorithm(benchmark::State& state) {
  auto request = make_three_fractures(8200e-6);
  request.algorithm = static_cast<int>(state.range(0));
  mesh::TriangleMesh m;
  for (auto _ : state) m = mesh::generate_mesh(request);
  set_mesh_counters(state, m);
}
BENCHMARK(BM_GenerateMeshAlgorithm)->Arg(1)->Arg(5)->Arg(6)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// Delaunay with Gmsh's threads (1 or 2) at about 3e5 triangles.
void BM_GenerateMeshThreads(benchmark::State& state) {
  auto request = make_three_fractures(3500e-6);
  request.threads = static_cast<int>(state.range(0));
  mesh::TriangleMesh m;
  for (auto _ : state) m = mesh::generate_mesh(request);
  set_mesh_counters(state, m);
}
BENCHMARK(BM_GenerateMeshThreads)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

void BM_SetupSolver(benchmark::State& state, const mesh::TriangleMesh& m) {
  for (auto _ : state) {
    hydro::DarcySolver solver(m, make_problem(), make_solver());
    benchmark::DoNotOptimize(solver.unknown_count());
  }
  set_mesh_counters(state, m);
}

// One coupling iteration's flow solve: new permeabilities (alternating k_f and 2 k_f so
// that every pass really refactors), everything after the set-up.
void BM_Solve(benchmark::State& state, const mesh::TriangleMesh& m) {
  hydro::DarcySolver solver(m, make_problem(), make_solver());
  // The analysis runs aside from the set-up on: waited for here, so that the first iteration
  // is timed as every other, not with the rest of the set-up.
  const double setup = solver.setup_seconds();
  const std::vector<double> k1 = make_permeability(m, kStripK), k2 = make_permeability(m, 2 * kStripK);
  hydro::SolveTimings sum;
  double balance = 0.0, refinements = 0.0, flow = 0.0;
  long passes = 0;
  for (auto _ : state) {
    const auto s = solver.solve(passes % 2 == 0 ? k1 : k2);
    sum.assemble += s.timings.assemble;
    sum.factorize += s.timings.factorize;
    sum.solve += s.timings.solve;
    sum.postprocess += s.timings.postprocess;
    balance = std::max(balance, s.balance_error);
    refinements += s.refinement_steps;
    if (passes == 0) flow = -s.boundary_flow("left");
    ++passes;
  }
  set_mesh_counters(state, m);
  state.counters["setup_s"] = setup;
  state.counters["assemble_s"] = sum.assemble / passes;
  state.counters["factorize_s"] = sum.factorize / passes;
  state.counters["solve_s"] = sum.solve / passes;
  state.counters["post_s"] = sum.postprocess / passes;
  state.counters["refine_steps"] = refinements / passes;
  state.counters["balance"] = balance;
  state.counters["flow_rel_err"] = flow / ((3 * kStripWidth * kStripK + (1 - 3 * kStripWidth) * kMatrixK) *
                                           hydro::Fluid{}.conductivity_per_permeability()) - 1.0;
}

// A layer like the seal of benchmarks/seal_scenario.py over a structured mesh of 1600 × 320
// cells (1,024,000 triangles, 0.0625 m): h = 50 m at the base, 0 at the top; beds every 0.2 m
// and joints every 1 m as strips of k = 1e-8 m² in a matrix of 1e-15 m².
const mesh::TriangleMesh& layer_mesh() {
  static const mesh::TriangleMesh m = [] {
    constexpr int nx = 1600, ny = 320;
    mesh::TriangleMesh out;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) out.nodes.push_back({100.0 * i / nx, 20.0 * j / ny});
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int a = j * (nx + 1) + i, b = a + 1, d = a + nx + 1, c = d + 1;
        out.triangles.push_back({a, b, c});
        out.triangles.push_back({a, c, d});
      }
    out.region.assign(out.triangles.size(), 0);
    out.region_names = {"domain"};
    mesh::name_boundary_edges(out, {}, geometry::bounding_box(out.nodes));
    return out;
  }();
  return m;
}

// The layer's permeability at a pass: each fracture element's k moved by up to ±`spread` from
// the kept factor's (a fixed pattern, its phase changing with the pass); and the first `closed`
// fracture elements past x = 50 m (a stretch of a bed) closed to the matrix's k, a jump of 1e7.
std::vector<double> layer_permeability(double spread, int pass, long closed = 0) {
  const mesh::TriangleMesh& m = layer_mesh();
  std::vector<double> k(m.triangles.size(), kMatrixK);
  for (std::size_t e = 0; e < k.size(); ++e) {
    const auto& t = m.triangles[e];
    const geometry::Point c = (m.nodes[t[0]] + m.nodes[t[1]] + m.nodes[t[2]]) / 3.0;
    const bool bed = std::abs(std::fmod(c.y, 0.2) - 0.1) > 0.07, joint = std::abs(std::fmod(c.x, 1.0) - 0.5) > 0.47;
    if (!bed && !joint) continue;
    if (c.x > 50.0 && closed > 0) {
      --closed;
      continue;
    }
    k[e] = 1e-8 * (1.0 + spread * std::sin(0.7 * static_cast<double>(e) + pass));
  }
  return k;
}

// A late coupling pass's flow solve on the layer: the permeability of the fractures moved by
// up to ±(arg / 1000) since the pass that factored, and (third argument) that many elements of
// one bed closed. Afresh (arg 0 of the second argument): the exact solve, factor and
// refinement, as every pass did before; on the kept factor (1): CG preconditioned by it,
// corrected for the closed elements where they are few. CPU time; run with
// OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1.
void BM_LatePassFlow(benchmark::State& state) {
  const double spread = state.range(0) * 1e-3;
  const bool reuse = state.range(1) == 1;
  const long closed = state.range(2);
  hydro::DarcyProblem problem;
  problem.boundaries = {{"bottom", hydro::BoundaryKind::head, 50.0}, {"top", hydro::BoundaryKind::head, 0.0}};
  hydro::DarcySolver solver(layer_mesh(), problem, make_solver());
  std::vector<std::vector<double>> passes;
  for (int pass = 0; pass < 4; ++pass) passes.push_back(layer_permeability(spread, pass + 1, closed));
  std::vector<double> heads = solver.solve(layer_permeability(0.0, 0)).head;  // the pass that factored
  double balance = 0.0, iterations = 0.0, afresh = 0.0, corrected = 0.0;
  hydro::SolveTimings phases;
  long count = 0;
  for (auto _ : state) {
    const auto& k = passes[count % passes.size()];
    const hydro::FlowSolution s = reuse ? solver.solve_reusing_factor(k, heads) : solver.solve(k);
    balance = std::max(balance, s.balance_error);
    iterations += s.cg_iterations;
    afresh += s.factorised;
    corrected += s.corrected_elements;
    phases.assemble += s.timings.assemble;
    phases.factorize += s.timings.factorize;
    phases.solve += s.timings.solve;
    phases.postprocess += s.timings.postprocess;
    ++count;
    if (reuse && s.factorised) {  // the pass that factored anew: the kept factor is back to k0
      state.PauseTiming();
      heads = solver.solve(layer_permeability(0.0, 0)).head;
      state.ResumeTiming();
    }
  }
  set_mesh_counters(state, layer_mesh());
  state.counters["cg_iterations"] = iterations / count;
  state.counters["factored_afresh"] = afresh / count;
  state.counters["corrected_elements"] = corrected / count;
  state.counters["balance"] = balance;
  state.counters["assemble_s"] = phases.assemble / count;    // each phase's seconds a pass
  state.counters["factorize_s"] = phases.factorize / count;
  state.counters["solve_s"] = phases.solve / count;          // the solves and CG iterations
  state.counters["postprocess_s"] = phases.postprocess / count;
}

BENCHMARK(BM_LatePassFlow)
    ->Args({10, 0, 0})->Args({10, 1, 0})->Args({100, 1, 0})->Args({10, 1, 60})->Args({10, 1, 400})
    ->Unit(benchmark::kSecond)->Iterations(4);

void register_own_meshes() {
  // Far-field sizes (µm) giving about 1e4, 1e5 and 1e6 triangles.
  for (long size_um : {45000L, 8200L, 1650L}) {
    benchmark::RegisterBenchmark("BM_GenerateMesh", BM_GenerateMesh)
        ->Arg(size_um)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(size_um < 10000 ? 1 : 3);
    const std::string size = std::to_string(size_um);
    benchmark::RegisterBenchmark(std::string("BM_SetupSolver/").append(size).c_str(),
                                 [size_um](benchmark::State& s) { BM_SetupSolver(s, get_mesh(size_um)); })
        ->Unit(benchmark::kSecond)->UseRealTime()->Iterations(size_um < 10000 ? 1 : 5);
    benchmark::RegisterBenchmark(std::string("BM_Solve/").append(size).c_str(),
                                 [size_um](benchmark::State& s) { BM_Solve(s, get_mesh(size_um)); })
        ->Unit(benchmark::kSecond)->UseRealTime()->Iterations(size_um < 10000 ? 4 : 10);
  }
}

void register_peer_mesh() {
  const char* path = std::getenv("HYDRODDA_PEER_MESH");
  if (!path) return;
  static mesh::TriangleMesh peer;
  static double read_seconds = 0.0;
  const auto start = std::chrono::steady_clock::now();
  peer = mesh::read_msh(path);
  read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  benchmark::RegisterBenchmark("BM_SetupSolver/PeerMesh", [](benchmark::State& s) {
    BM_SetupSolver(s, peer);
    s.counters["read_s"] = read_seconds;
  })->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
  benchmark::RegisterBenchmark("BM_Solve/PeerMesh", [](benchmark::State& s) { BM_Solve(s, peer); })
      ->Unit(benchmark::kSecond)->UseRealTime()->Iterations(6);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  register_peer_mesh();
  register_own_meshes();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
