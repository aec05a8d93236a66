// The .vtu/.pvd writers, checked by reading the files back with VTK's own XML readers
// (python3-vtk9, or the VTK inside python3-paraview, through tests/output/check_vtu.py) and
// with our own decoder of the compressed blocks. The arrays are raw IEEE doubles, and repr()
// prints a double so that it reads back to itself, so every value must come back exactly.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "output/pvd_series.hpp"
#include "output/vtk_writer.hpp"
#include "output/zlib_blocks.hpp"

#include "appended_arrays.hpp"

namespace hydrodda::output {
namespace {

namespace fs = std::filesystem;
using geometry::Point;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The first interpreter that can import vtk: $HYDRODDA_VTK_PYTHON, python3 on PATH, then
// Debian's own python3 (where python3-vtk9 or python3-paraview installs VTK's modules).
std::optional<std::string> find_vtk_python() {
  std::vector<std::string> candidates;
  if (const char* env = std::getenv("HYDRODDA_VTK_PYTHON")) candidates.emplace_back(env);
  candidates.emplace_back("python3");
  candidates.emplace_back("/usr/bin/python3");
  for (const std::string& python : candidates) {
    const std::string probe =
        python + " -c \"import vtkmodules.vtkIOXML\" > /dev/null 2>&1";
    if (std::system(probe.c_str()) == 0) return python;
  }
  return std::nullopt;
}

// What check_vtu.py printed, split into whitespace-separated tokens per line.
struct Readback {
  int status = -1;
  std::vector<std::vector<std::string>> lines;

  std::vector<std::vector<std::string>> with(const std::string& key) const {
    std::vector<std::vector<std::string>> found;
    for (const auto& l : lines) {
      if (!l.empty() && l[0] == key) found.push_back(l);
    }
    return found;
  }
  long count(const std::string& key) const {
    const auto found = with(key);
    return found.size() == 1 && found[0].size() == 2 ? std::stol(found[0][1]) : -1;
  }
  // Component count of a point or cell array, -1 when absent.
  int components(const std::string& kind, const std::string& name) const {
    for (const auto& l : with(kind + "_array")) {
      if (l.size() == 4 && l[1] == name) return std::stoi(l[2]);
    }
    return -1;
  }
  std::vector<std::string> array_names(const std::string& kind) const {
    std::vector<std::string> names;
    for (const auto& l : with(kind + "_array")) names.push_back(l[1]);
    return names;
  }
  double value(const std::string& kind, const std::string& name, int tuple, int comp) const {
    for (const auto& l : with(kind + "_value")) {
      if (l.size() == 5 && l[1] == name && std::stoi(l[2]) == tuple && std::stoi(l[3]) == comp) {
        return std::stod(l[4]);
      }
    }
    ADD_FAILURE() << "no " << kind << " value " << name << "[" << tuple << "][" << comp << "]";
    return NAN;
  }
  Point point(int i) const {
    for (const auto& l : with("point")) {
      if (l.size() == 5 && std::stoi(l[1]) == i) {
        EXPECT_EQ(std::stod(l[4]), 0.0) << "z of point " << i;
        return {std::stod(l[2]), std::stod(l[3])};
      }
    }
    ADD_FAILURE() << "no point " << i;
    return {NAN, NAN};
  }
  // {type, node ids...} of cell i.
  std::vector<long> cell(int i) const {
    for (const auto& l : with("cell")) {
      if (l.size() >= 3 && std::stoi(l[1]) == i) {
        std::vector<long> out;
        for (std::size_t k = 2; k < l.size(); ++k) out.push_back(std::stol(l[k]));
        return out;
      }
    }
    ADD_FAILURE() << "no cell " << i;
    return {};
  }
};

Readback read_back(const std::string& python, const fs::path& file) {
  const std::string command = python + " " + HYDRODDA_SOURCE_DIR "/tests/output/check_vtu.py '" +
                              file.string() + "'";
  Readback result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::string text;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) text += buffer.data();
  result.status = pclose(pipe);
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream tokens(line);
    std::vector<std::string> row;
    for (std::string t; tokens >> t;) row.push_back(t);
    result.lines.push_back(row);
  }
  return result;
}

// Binary Float64 reads back bit for bit.
void expect_same(double a, double b, const std::string& what) {
  EXPECT_EQ(a, b) << what;
}

class VtkWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto found = find_vtk_python();
    if (!found) GTEST_SKIP() << "python3 cannot import vtk (Debian package python3-paraview or python3-vtk9)";
    python_ = *found;
    dir_ = fresh_dir("hydrodda-vtk-writer-" + std::string(
        ::testing::UnitTest::GetInstance()->current_test_info()->name()));
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  std::string python_;
  fs::path dir_;
};

TEST_F(VtkWriter, TrianglesRoundTripPointsCellsAndArrays) {
  // Unit square split along its diagonal, with awkward decimals for the round trip.
  const std::vector<Point> nodes{
      {0.1, 0.2}, {1.0 / 3.0, -2.5e-7}, {1e5, 7.0 / 9.0}, {-3.0, 1e-300}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  const std::vector<DataArray> point_data{
      {"pressure", 1, {1.5, -2.0 / 7.0, 3e8, 0.0}},
      {"velocity", 2, {1, 2, 3, 4, 5, 6, 7.125, -8e-9}}};
  const std::vector<DataArray> cell_data{
      {"permeability", 1, {1e-12, 3.3e-15}},
      {"flux", 2, {0.5, -0.25, 1.0 / 3.0, 2.0 / 3.0}},
      {"stress", 3, {1, 2, 3, 4, 5, 6}}};
  const fs::path file = dir_ / "mesh.vtu";
  write_vtu_triangles(file, nodes, triangles, point_data, cell_data);

  const Readback r = read_back(python_, file);
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.count("points"), 4);
  EXPECT_EQ(r.count("cells"), 2);
  EXPECT_EQ(r.cell(0), (std::vector<long>{5, 0, 1, 2}));
  EXPECT_EQ(r.cell(1), (std::vector<long>{5, 0, 2, 3}));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(r.point(i).x, nodes[i].x) << "node " << i;
    EXPECT_EQ(r.point(i).y, nodes[i].y) << "node " << i;
  }
  EXPECT_EQ(r.array_names("point"), (std::vector<std::string>{"pressure", "velocity"}));
  EXPECT_EQ(r.array_names("cell"), (std::vector<std::string>{"permeability", "flux", "stress"}));
  EXPECT_EQ(r.components("point", "pressure"), 1);
  EXPECT_EQ(r.components("point", "velocity"), 3);  // 2D vector padded with z = 0
  EXPECT_EQ(r.components("cell", "flux"), 3);
  EXPECT_EQ(r.components("cell", "stress"), 3);
  for (int t = 0; t < 4; ++t) {
    expect_same(r.value("point", "pressure", t, 0), point_data[0].values[t], "pressure");
    expect_same(r.value("point", "velocity", t, 0), point_data[1].values[2 * t], "velocity x");
    expect_same(r.value("point", "velocity", t, 1), point_data[1].values[2 * t + 1], "velocity y");
    EXPECT_EQ(r.value("point", "velocity", t, 2), 0.0);
  }
  for (int t = 0; t < 2; ++t) {
    expect_same(r.value("cell", "permeability", t, 0), cell_data[0].values[t], "permeability");
    expect_same(r.value("cell", "flux", t, 0), cell_data[1].values[2 * t], "flux x");
    expect_same(r.value("cell", "flux", t, 1), cell_data[1].values[2 * t + 1], "flux y");
    EXPECT_EQ(r.value("cell", "flux", t, 2), 0.0);
    for (int c = 0; c < 3; ++c) {
      expect_same(r.value("cell", "stress", t, c), cell_data[2].values[3 * t + c], "stress");
    }
  }
}

TEST_F(VtkWriter, PolygonsKeepTheirOwnVertices) {
  const std::vector<std::vector<Point>> blocks{
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
      {{2, 0}, {3.5, 0.25}, {2.5, 1.75}},
      {{4, 0}, {5, 0}, {5.5, 1}, {4.5, 2}, {3.75, 1}}};
  const std::vector<DataArray> cell_data{{"block_id", 1, {0, 1, 2}},
                                         {"displacement", 2, {0.1, 0.2, -0.3, 0.4, 5e-6, -6e-6}}};
  const fs::path file = dir_ / "blocks.vtu";
  write_vtu_polygons(file, blocks, cell_data);

  const Readback r = read_back(python_, file);
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.count("points"), 12);
  EXPECT_EQ(r.count("cells"), 3);
  EXPECT_EQ(r.cell(0), (std::vector<long>{7, 0, 1, 2, 3}));
  EXPECT_EQ(r.cell(1), (std::vector<long>{7, 4, 5, 6}));
  EXPECT_EQ(r.cell(2), (std::vector<long>{7, 7, 8, 9, 10, 11}));
  EXPECT_EQ(r.point(5).x, 3.5);
  EXPECT_EQ(r.point(11).x, 3.75);
  EXPECT_TRUE(r.array_names("point").empty());
  EXPECT_EQ(r.components("cell", "block_id"), 1);
  EXPECT_EQ(r.components("cell", "displacement"), 3);
  for (int t = 0; t < 3; ++t) {
    EXPECT_EQ(r.value("cell", "block_id", t, 0), t);
    expect_same(r.value("cell", "displacement", t, 0), cell_data[1].values[2 * t], "ux");
    expect_same(r.value("cell", "displacement", t, 1), cell_data[1].values[2 * t + 1], "uy");
  }
}

TEST_F(VtkWriter, SegmentsAreLines) {
  const std::vector<std::array<Point, 2>> segments{
      {{{0, 0}, {1, 0}}}, {{{1, 0}, {1, 2}}}, {{{-0.5, 0.25}, {2, 2}}}};
  const std::vector<DataArray> cell_data{{"aperture", 1, {1e-4, 2.5e-5, 3.0 / 7.0 * 1e-3}},
                                         {"normal", 2, {0, 1, -1, 0, 0.6, 0.8}}};
  const fs::path file = dir_ / "contacts.vtu";
  write_vtu_segments(file, segments, cell_data);

  const Readback r = read_back(python_, file);
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.count("points"), 6);
  EXPECT_EQ(r.count("cells"), 3);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(r.cell(c), (std::vector<long>{3, 2 * c, 2 * c + 1}));
  EXPECT_EQ(r.point(4).x, -0.5);
  EXPECT_EQ(r.point(5).y, 2.0);
  EXPECT_EQ(r.components("cell", "normal"), 3);
  for (int t = 0; t < 3; ++t) {
    expect_same(r.value("cell", "aperture", t, 0), cell_data[0].values[t], "aperture");
    expect_same(r.value("cell", "normal", t, 1), cell_data[1].values[2 * t + 1], "normal y");
  }
}

TEST_F(VtkWriter, EmptyGridIsReadable) {
  const fs::path file = dir_ / "none.vtu";
  write_vtu_segments(file, {}, std::vector<DataArray>{{"aperture", 1, {}}});
  const Readback r = read_back(python_, file);
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.count("points"), 0);
  EXPECT_EQ(r.count("cells"), 0);
}

// A strip of triangles over n nodes (i, i+1, i+2), so the arrays can be sized to VTK's 32 KiB
// compression blocks: n = 4096 makes the point array exactly one full block (the header's
// partial-block size is then 0) and the points (x, y, 0) exactly three.
struct Strip {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;
  std::vector<DataArray> point_data;
  std::vector<DataArray> cell_data;
};

Strip make_strip(int n) {
  Strip s;
  DataArray head{"head", 1, {}}, stress{"stress", 3, {}};
  for (int i = 0; i < n; ++i) {
    s.nodes.push_back({i * 0.1, (i % 2) * std::sqrt(2.0) + i * 1e-7});
    head.values.push_back(std::sin(i) * 1e3 + 1.0 / (i + 3));
  }
  for (int i = 0; i + 2 < n; ++i) {
    s.triangles.push_back({i, i + 1, i + 2});
    stress.values.insert(stress.values.end(), {-1e6 / (i + 1), 2e5 * std::cos(i), std::exp(-i * 1e-3)});
  }
  s.point_data = {head};
  s.cell_data = {stress};
  return s;
}

TEST_F(VtkWriter, ArraysAcrossCompressionBlocksReadBackAtEveryLevel) {
  const Strip s = make_strip(4096);  // head: 1 full block; stress: 3 blocks, the last partial
  ASSERT_EQ(s.point_data[0].values.size() * sizeof(double), zlib_block_size);
  for (int level : {0, VtuCompression{}.level, 9}) {
    const fs::path file = dir_ / ("strip_" + std::to_string(level) + ".vtu");
    write_vtu_triangles(file, s.nodes, s.triangles, s.point_data, s.cell_data, {level});
    const Readback r = read_back(python_, file);
    ASSERT_EQ(r.status, 0) << "level " << level;
    ASSERT_EQ(r.count("points"), 4096);
    ASSERT_EQ(r.count("cells"), 4094);
    for (int i : {0, 4095, 2048, 1365}) {  // 1365 × 24 bytes straddles the first block's end
      EXPECT_EQ(r.point(i).x, s.nodes[i].x) << "level " << level << " node " << i;
      EXPECT_EQ(r.point(i).y, s.nodes[i].y) << "level " << level << " node " << i;
      expect_same(r.value("point", "head", i, 0), s.point_data[0].values[i], "head");
    }
    for (int t : {0, 1365, 4093}) {
      EXPECT_EQ(r.cell(t), (std::vector<long>{5, t, t + 1, t + 2})) << "level " << level;
      for (int c = 0; c < 3; ++c) expect_same(r.value("cell", "stress", t, c), s.cell_data[0].values[3 * t + c], "stress");
    }
  }
}

TEST_F(VtkWriter, PvdSeriesListsEveryStepWithExactTimes) {
  const std::vector<std::array<Point, 2>> segment{{{{0, 0}, {1, 1}}}};
  const std::vector<double> times{0.0, 0.1, 1.0 / 3.0, 2.5e-7 + 1.0};
  PvdSeries series(dir_ / "run.pvd");
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string name = "contacts_" + std::to_string(i) + ".vtu";
    write_vtu_segments(dir_ / name, segment, {});
    series.add(times[i], name, 2);
    // Rewritten after each step: the file on disk lists exactly the steps so far.
    const Readback r = read_back(python_, dir_ / "run.pvd");
    ASSERT_EQ(r.status, 0);
    ASSERT_EQ(r.with("dataset").size(), i + 1);
  }
  const Readback r = read_back(python_, dir_ / "run.pvd");
  ASSERT_EQ(r.status, 0);
  const auto datasets = r.with("dataset");
  ASSERT_EQ(datasets.size(), times.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_EQ(std::stod(datasets[i][1]), times[i]) << "step " << i;  // exact
    EXPECT_EQ(datasets[i][2], "2");
    EXPECT_EQ(datasets[i][3], "contacts_" + std::to_string(i) + ".vtu");
  }
  EXPECT_EQ(r.with("cells").size(), times.size());
}

// The layout, read with our own decoder (appended_arrays.hpp, no VTK needed): the attributes
// ParaView's writer sets, every array appended raw after one underscore at the offset its
// element names, compressed in VTK's blocks, holding exactly the bytes given.
TEST(VtkWriterLayout, AppendedCompressedArraysAsParaViewWritesThem) {
  const fs::path dir = fresh_dir("hydrodda-vtk-writer-layout");
  const Strip s = make_strip(5000);
  write_vtu_triangles(dir / "strip.vtu", s.nodes, s.triangles, s.point_data, s.cell_data);
  const std::string file = testing::read_file_bytes(dir / "strip.vtu");
  const std::string head = file.substr(0, file.find("<UnstructuredGrid>"));
  EXPECT_NE(head.find("type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_NE(head.find("byte_order=\"LittleEndian\""), std::string::npos);
  EXPECT_NE(head.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(head.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_EQ(file.find("format=\"ascii\""), std::string::npos);
  EXPECT_TRUE(file.ends_with("\n  </AppendedData>\n</VTKFile>\n"));

  const auto arrays = testing::decode_appended(file);
  ASSERT_EQ(arrays.size(), 6u);  // head, stress, Points, connectivity, offsets, types
  EXPECT_EQ(arrays[0].name, "head");
  EXPECT_EQ(testing::values_of<double>(arrays[0].bytes), s.point_data[0].values);
  EXPECT_EQ(arrays[1].name, "stress");
  EXPECT_EQ(arrays[1].components, 3);
  EXPECT_EQ(testing::values_of<double>(arrays[1].bytes), s.cell_data[0].values);
  EXPECT_EQ(arrays[2].name, "Points");
  const auto xyz = testing::values_of<double>(arrays[2].bytes);
  ASSERT_EQ(xyz.size(), 3 * s.nodes.size());
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    ASSERT_EQ(xyz[3 * i], s.nodes[i].x);
    ASSERT_EQ(xyz[3 * i + 1], s.nodes[i].y);
    ASSERT_EQ(xyz[3 * i + 2], 0.0);
  }
  EXPECT_EQ(arrays[3].type, "Int64");
  const auto connectivity = testing::values_of<std::int64_t>(arrays[3].bytes);
  const auto offsets = testing::values_of<std::int64_t>(arrays[4].bytes);
  ASSERT_EQ(offsets.size(), s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    ASSERT_EQ(offsets[t], static_cast<std::int64_t>(3 * t + 3));
    for (int k = 0; k < 3; ++k) ASSERT_EQ(connectivity[3 * t + k], s.triangles[t][k]);
  }
  EXPECT_EQ(arrays[5].type, "UInt8");
  EXPECT_EQ(arrays[5].bytes, std::string(s.triangles.size(), '\x05'));  // VTK_TRIANGLE
  fs::remove_all(dir);
}

// Validation needs no reader.
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument)";
}

void expect_mentions(const std::string& message, const std::string& needle) {
  EXPECT_NE(message.find(needle), std::string::npos) << "message: " << message;
}

TEST(VtkWriterErrors, SizeMismatchesNameTheArray) {
  const fs::path dir = fresh_dir("hydrodda-vtk-writer-errors");
  const std::vector<Point> nodes{{0, 0}, {1, 0}, {0, 1}};
  const std::vector<std::array<int, 3>> triangle{{0, 1, 2}};
  const auto triangles_with = [&](std::vector<DataArray> point_data,
                                  std::vector<DataArray> cell_data) {
    return message_of([&] {
      write_vtu_triangles(dir / "t.vtu", nodes, triangle, point_data, cell_data);
    });
  };
  expect_mentions(triangles_with({{"pressure", 1, {1, 2}}}, {}),
                  "point array 'pressure' has 2 values; expected 3");
  expect_mentions(triangles_with({}, {{"flux", 2, {1, 2, 3}}}),
                  "cell array 'flux' has 3 values; expected 2");
  expect_mentions(triangles_with({{"head", 0, {}}}, {}), "'head' has 0 components");
  expect_mentions(triangles_with({{"", 1, {1, 2, 3}}}, {}), "empty name");
  expect_mentions(triangles_with({{"p", 1, {1, 2, 3}}, {"p", 1, {1, 2, 3}}}, {}),
                  "'p' appears twice");
  expect_mentions(triangles_with({{"p", 1, {1, NAN, 3}}}, {}),
                  "'p' has a non-finite value at index 1");

  const std::vector<std::array<int, 3>> bad_triangle{{0, 1, 3}};
  expect_mentions(
      message_of([&] { write_vtu_triangles(dir / "t.vtu", nodes, bad_triangle, {}, {}); }),
      "triangle 0 refers to node 3");
  const std::vector<std::vector<Point>> sliver{{{0, 0}, {1, 0}}};
  expect_mentions(message_of([&] { write_vtu_polygons(dir / "b.vtu", sliver, {}); }),
                  "polygon 0 has 2 vertices");
  const std::vector<std::array<Point, 2>> segment{{{{0, 0}, {1, 1}}}};
  const std::vector<DataArray> short_aperture{{"aperture", 1, {1, 2}}};
  expect_mentions(
      message_of([&] { write_vtu_segments(dir / "s.vtu", segment, short_aperture); }),
      "'aperture' has 2 values; expected 1");

  expect_mentions(
      message_of([&] { write_vtu_segments(dir / "s.vtu", segment, {}, VtuCompression{10}); }),
      "compression level 10");

  PvdSeries series(dir / "run.pvd");
  EXPECT_THROW(series.add(NAN, "a.vtu"), std::invalid_argument);
  EXPECT_THROW(series.add(0.0, ""), std::invalid_argument);
  // Validation comes before writing: a rejected call leaves no file.
  EXPECT_FALSE(fs::exists(dir / "t.vtu"));
  EXPECT_FALSE(fs::exists(dir / "b.vtu"));
  EXPECT_FALSE(fs::exists(dir / "s.vtu"));
  EXPECT_FALSE(fs::exists(dir / "run.pvd"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hydrodda::output
