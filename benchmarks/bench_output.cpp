// Writing the ParaView files: time and size of one .vtu of each series a run writes.
//   build/bin/bench_output
// Cases, with the arrays the program writes (src/cli/paraview_output.cpp):
//   fluid/N: a unit square of N = 2 n² triangles on jittered nodes; points: head, pressure;
//     cells: permeability, porosity, flux (a vector), region. The porosity is the real mapping
//     of 8 × 8 blocks 0.5% apart, the permeability Kozeny–Carman of it, the head a smooth field
//     and the flux −K ∇h of its P1 interpolant, so the numbers carry full mantissas as a run's do.
//   blocks: the 1,601-block brick wall of brickwall.py 40 40 after its 20 static steps; cells:
//     block, displacement, rotation, stress, area.
//   contacts: that wall's contacts, one line each; cells: state, normal_force, penetration,
//     aperture, block_i, block_j.
// The second argument is zlib's level (0 stores the bytes uncompressed). With libvtk9-dev
// installed, BM_Vtk* write the same data through VTK's own vtkXMLUnstructuredGridWriter
// (appended raw, UInt64 headers, zlib at the same level), the grid built from our arrays
// inside the timing as a program would have to.
// Counters: `bytes` (the file's size) and `MB/s` of that size. Wall time includes the fsync of
// our atomic write (VTK's writer does not fsync); CPU time does not.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "coupling/porosity.hpp"
#include "dda/system.hpp"
#include "dda/test_models.hpp"  // tests/dda: the brick wall the tests and ntdda run
#include "geometry/polygon.hpp"
#include "hydro/permeability_law.hpp"
#include "output/vtk_writer.hpp"

#ifdef HYDRODDA_BENCH_VTK
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>
#endif

namespace {

namespace fs = std::filesystem;
using hydrodda::geometry::Point;
using hydrodda::geometry::Polygon;
using hydrodda::output::DataArray;

struct Fluid {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;
  std::vector<DataArray> point_data;
  std::vector<DataArray> cell_data;
};

// A deterministic jitter in [-0.5, 0.5) from an integer (a 64-bit mix, not a generator, so the
// case is the same on every machine).
double jitter(std::uint64_t k) {
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdULL;
  k ^= k >> 33;
  k *= 0xc4ceb9fe1a85ec53ULL;
  k ^= k >> 33;
  return static_cast<double>(k >> 11) / 9007199254740992.0 - 0.5;
}

Fluid make_fluid(int n) {
  Fluid f;
  const double h = 1.0 / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inner_x = i > 0 && i < n, inner_y = j > 0 && j < n;
      const std::uint64_t k = static_cast<std::uint64_t>(j) * (n + 1) + i;
      f.nodes.push_back({i * h + (inner_x ? 0.3 * h * jitter(2 * k) : 0.0),
                         j * h + (inner_y ? 0.3 * h * jitter(2 * k + 1) : 0.0)});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, d = a + n + 1, e = d + 1;
      f.triangles.push_back({a, b, e});
      f.triangles.push_back({a, e, d});
    }
  constexpr int blocks = 8;
  const double size = 1.0 / blocks, gap = 0.005 * size;
  std::vector<Polygon> cover;
  for (int j = 0; j < blocks; ++j)
    for (int i = 0; i < blocks; ++i) {
      const double x0 = i * size + gap, y0 = j * size + gap, x1 = (i + 1) * size - gap, y1 = (j + 1) * size - gap;
      cover.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    }
  const auto porosity = hydrodda::coupling::PorosityMapper(f.nodes, f.triangles).compute(cover, 0.1).porosity;

  constexpr double rho_g = 1000.0 * 9.81, mu = 1e-3;
  const auto head = [](Point p) { return 20.0 * (1.0 - p.x) + 0.3 * std::sin(3.0 * p.x) * std::cos(2.0 * p.y); };
  DataArray head_array{"head", 1, {}}, pressure{"pressure", 1, {}};
  for (const Point& p : f.nodes) {
    head_array.values.push_back(head(p));
    pressure.values.push_back(rho_g * head(p));
  }
  DataArray permeability{"permeability", 1, {}}, flux{"flux", 2, {}}, region{"region", 1, {}};
  for (std::size_t t = 0; t < f.triangles.size(); ++t) {
    const double k = hydrodda::hydro::kozeny_carman_permeability(porosity[t], 1.2e-5, 9.869e-11);
    permeability.values.push_back(k);
    // ∇h of the P1 interpolant: solve [x1−x0 y1−y0; x2−x0 y2−y0] g = [h1−h0; h2−h0].
    const Point p0 = f.nodes[f.triangles[t][0]], p1 = f.nodes[f.triangles[t][1]], p2 = f.nodes[f.triangles[t][2]];
    const double a = p1.x - p0.x, b = p1.y - p0.y, c = p2.x - p0.x, d = p2.y - p0.y;
    const double dh1 = head(p1) - head(p0), dh2 = head(p2) - head(p0), det = a * d - b * c;
    const double gx = (d * dh1 - b * dh2) / det, gy = (a * dh2 - c * dh1) / det;
    const double conductivity = k * rho_g / mu;
    flux.values.insert(flux.values.end(), {-conductivity * gx, -conductivity * gy});
    region.values.push_back(0.0);
  }
  f.point_data = {head_array, pressure};
  f.cell_data = {permeability, {"porosity", 1, porosity}, flux, region};
  return f;
}

// The brick wall after its 20 static steps, as the program writes it.
struct Wall {
  std::vector<Polygon> polygons;
  std::vector<DataArray> block_data;
  std::vector<std::array<Point, 2>> segments;
  std::vector<DataArray> contact_data;
};

Wall make_wall() {
  hydrodda::dda::System system(hydrodda::dda::testing::make_brick_wall(40, 40));
  system.run_steps(20);
  Wall w;
  DataArray id{"block", 1, {}}, displacement{"displacement", 2, {}}, rotation{"rotation", 1, {}},
      stress{"stress", 3, {}}, area{"area", 1, {}};
  for (int b = 0; b < system.block_count(); ++b) {
    w.polygons.push_back(system.polygon(b));
    id.values.push_back(b);
    const Point u = system.displacement(b);
    displacement.values.insert(displacement.values.end(), {u.x, u.y});
    rotation.values.push_back(system.rotation(b));
    const auto s = system.stress(b);
    stress.values.insert(stress.values.end(), s.begin(), s.end());
    area.values.push_back(system.area(b));
  }
  w.block_data = {id, displacement, rotation, stress, area};
  DataArray state{"state", 1, {}}, normal_force{"normal_force", 1, {}}, penetration{"penetration", 1, {}},
      aperture{"aperture", 1, {}}, block_i{"block_i", 1, {}}, block_j{"block_j", 1, {}};
  for (const auto& c : system.contacts()) {
    const Polygon vertex_block = system.polygon(c.key.block_i), edge_block = system.polygon(c.key.block_j);
    const Point p = vertex_block[c.key.vertex];
    const Point a = edge_block[c.key.edge], b = edge_block[(c.key.edge + 1) % edge_block.size()];
    w.segments.push_back({p, hydrodda::geometry::closest_point_on_segment(p, a, b)});
    state.values.push_back(static_cast<double>(c.state));
    normal_force.values.push_back(c.normal_force);
    penetration.values.push_back(c.penetration);
    aperture.values.push_back(std::max(0.0, -c.penetration));
    block_i.values.push_back(c.key.block_i);
    block_j.values.push_back(c.key.block_j);
  }
  w.contact_data = {state, normal_force, penetration, aperture, block_i, block_j};
  return w;
}

const Wall& wall() {
  static const Wall w = make_wall();
  return w;
}

fs::path scratch_file(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "hydrodda-bench-output";
  fs::create_directories(dir);
  return dir / name;
}

void time_writes(benchmark::State& state, const fs::path& file, const std::function<void()>& write) {
  for (auto _ : state) write();
  const auto bytes = static_cast<double>(fs::file_size(file));
  state.counters["bytes"] = bytes;
  state.counters["MB/s"] = benchmark::Counter(bytes * 1e-6 * static_cast<double>(state.iterations()),
                                              benchmark::Counter::kIsRate);
  fs::remove(file);
}

hydrodda::output::VtuCompression level_of(const benchmark::State& state, int argument) {
  return {static_cast<int>(state.range(argument))};
}

void BM_Fluid(benchmark::State& state) {
  const Fluid f = make_fluid(static_cast<int>(state.range(0)));
  const fs::path file = scratch_file("fluid.vtu");
  time_writes(state, file, [&] {
    hydrodda::output::write_vtu_triangles(file, f.nodes, f.triangles, f.point_data, f.cell_data, level_of(state, 1));
  });
  state.counters["triangles"] = static_cast<double>(f.triangles.size());
}
// n = 224: 100,352 triangles; n = 708: 1,002,528.
BENCHMARK(BM_Fluid)
    ->ArgsProduct({{224}, {0, 1, 2, 3, 4, 5, 6, 9}})
    ->ArgsProduct({{708}, {1, 2, 3, 6}})
    ->Unit(benchmark::kMillisecond);

void BM_Blocks(benchmark::State& state) {
  const Wall& w = wall();
  const fs::path file = scratch_file("blocks.vtu");
  time_writes(state, file, [&] { hydrodda::output::write_vtu_polygons(file, w.polygons, w.block_data, level_of(state, 0)); });
  state.counters["blocks"] = static_cast<double>(w.polygons.size());
}
BENCHMARK(BM_Blocks)->DenseRange(0, 6)->Arg(9)->Unit(benchmark::kMillisecond);

void BM_Contacts(benchmark::State& state) {
  const Wall& w = wall();
  const fs::path file = scratch_file("contacts.vtu");
  time_writes(state, file, [&] { hydrodda::output::write_vtu_segments(file, w.segments, w.contact_data, level_of(state, 0)); });
  state.counters["contacts"] = static_cast<double>(w.segments.size());
}
BENCHMARK(BM_Contacts)->DenseRange(0, 6)->Arg(9)->Unit(benchmark::kMillisecond);

#ifdef HYDRODDA_BENCH_VTK
// Our arrays copied into VTK's: 2-component vectors gain z = 0 as in our files.
void add_vtk_arrays(vtkDataSetAttributes& attributes, const std::vector<DataArray>& arrays) {
  for (const DataArray& a : arrays) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(a.name.c_str());
    const int components = a.components == 2 ? 3 : a.components;
    array->SetNumberOfComponents(components);
    const auto tuples = static_cast<vtkIdType>(a.values.size() / a.components);
    array->SetNumberOfTuples(tuples);
    for (vtkIdType t = 0; t < tuples; ++t)
      for (int c = 0; c < components; ++c)
        array->SetTypedComponent(t, c, c < a.components ? a.values[t * a.components + c] : 0.0);
    attributes.AddArray(array);
  }
}

// Points and cells of one VTK cell type, each cell a list of point ids.
template <class Cells>
void write_with_vtk(const fs::path& file, std::span<const Point> points, const Cells& cells, int type,
                    const std::vector<DataArray>& point_data, const std::vector<DataArray>& cell_data, int level) {
  vtkNew<vtkPoints> vtk_points;
  vtk_points->SetDataTypeToDouble();
  vtk_points->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) vtk_points->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, 0.0);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(vtk_points);
  grid->Allocate(static_cast<vtkIdType>(cells.size()));
  std::vector<vtkIdType> ids;
  for (const auto& cell : cells) {
    ids.assign(cell.begin(), cell.end());
    grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
  }
  add_vtk_arrays(*grid->GetPointData(), point_data);
  add_vtk_arrays(*grid->GetCellData(), cell_data);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(file.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(level);
  if (writer->Write() != 1) throw std::runtime_error("VTK writer failed on " + file.string());
}

// Each polygon's or segment's vertices as points of their own, as our writer lays them out.
template <class Shapes>
std::pair<std::vector<Point>, std::vector<std::vector<int>>> own_vertices(const Shapes& shapes) {
  std::vector<Point> points;
  std::vector<std::vector<int>> cells;
  for (const auto& shape : shapes) {
    cells.emplace_back();
    for (const Point& p : shape) {
      cells.back().push_back(static_cast<int>(points.size()));
      points.push_back(p);
    }
  }
  return {points, cells};
}

void BM_VtkFluid(benchmark::State& state) {
  const Fluid f = make_fluid(static_cast<int>(state.range(0)));
  const fs::path file = scratch_file("fluid_vtk.vtu");
  time_writes(state, file, [&] {
    write_with_vtk(file, f.nodes, f.triangles, VTK_TRIANGLE, f.point_data, f.cell_data, static_cast<int>(state.range(1)));
  });
}
BENCHMARK(BM_VtkFluid)
    ->ArgsProduct({{224}, {1, 6}})
    ->ArgsProduct({{708}, {1, 6}})
    ->Unit(benchmark::kMillisecond);

void BM_VtkBlocks(benchmark::State& state) {
  const Wall& w = wall();
  const auto [points, cells] = own_vertices(w.polygons);
  const fs::path file = scratch_file("blocks_vtk.vtu");
  time_writes(state, file, [&] {
    write_with_vtk(file, points, cells, VTK_POLYGON, {}, w.block_data, static_cast<int>(state.range(0)));
  });
}
BENCHMARK(BM_VtkBlocks)->Arg(1)->Arg(6)->Unit(benchmark::kMillisecond);

void BM_VtkContacts(benchmark::State& state) {
  const Wall& w = wall();
  const auto [points, cells] = own_vertices(w.segments);
  const fs::path file = scratch_file("contacts_vtk.vtu");
  time_writes(state, file, [&] {
    write_with_vtk(file, points, cells, VTK_LINE, {}, w.contact_data, static_cast<int>(state.range(0)));
  });
}
BENCHMARK(BM_VtkContacts)->Arg(1)->Arg(6)->Unit(benchmark::kMillisecond);
#endif

}  // namespace

BENCHMARK_MAIN();
