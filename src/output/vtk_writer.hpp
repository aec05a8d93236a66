#pragma once
// VTK XML unstructured-grid (.vtu) files for ParaView: the fluid mesh, the blocks and the
// contacts/fractures of one output step, laid out as ParaView's own writer lays them out:
// binary arrays (Float64 fields and points, Int64 cells, UInt8 types) appended raw after the
// XML, each compressed with zlib in VTK's blocks (zlib_blocks.hpp), UInt64 headers.
//
// Written by hand rather than through VTK's vtkXMLUnstructuredGridWriter: benchmarks/
// bench_output.cpp measures both on the same meshes (docs/performance.md, "Output"), and
// VTK's writer is no smaller nor faster at the same zlib level, while libvtk9-dev brings 181
// Debian packages (397 MB) into the build and cannot be installed beside python3-paraview.

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::output {

// One named field on points or cells: count * components numbers, tuple by tuple, held in
// `values` or, for a field the caller keeps anyway (a million-node head), borrowed in place.
// A 2-component field is written with 3 components (z = 0) so ParaView treats it as a vector.
struct DataArray {
  DataArray(std::string array_name, int array_components, std::vector<double> array_values = {})
      : name(std::move(array_name)), components(array_components), values(std::move(array_values)) {}
  // A field written from the caller's numbers, which must outlive the write.
  static DataArray view(std::string name, int components, std::span<const double> numbers) {
    DataArray a(std::move(name), components);
    a.borrowed_ = numbers;
    return a;
  }

  std::string name;
  int components = 1;
  std::vector<double> values;

  // The numbers written: the borrowed ones of a view, else `values`.
  std::span<const double> numbers() const {
    return borrowed_.data() ? borrowed_ : std::span<const double>(values);
  }

 private:
  std::span<const double> borrowed_;
};

// How the arrays are compressed: zlib's level, 0 (stored) to 9 (smallest). Level 1, measured
// with benchmarks/bench_output.cpp on a 10^5-triangle fluid file: 3.94 MB in 0.70 × 10^9
// instructions, where level 6 saves 2% (3.86 MB) for 2.2× the work and level 9 is no smaller
// than 6 and 18× slower than 1: the full-mantissa doubles of a field barely compress at any
// level (docs/performance.md, "Output").
struct VtuCompression {
  int level = 1;
};

// Triangles (VTK_TRIANGLE = 5) on shared nodes (x, y; z = 0 is written); each triangle is
// three indices into `nodes`. point_data has one tuple per node, cell_data one per triangle.
// Throws std::invalid_argument (naming the array or triangle) on any size or index mismatch,
// empty or duplicate names, or non-finite numbers.
void write_vtu_triangles(const std::filesystem::path& path,
                         std::span<const geometry::Point> nodes,
                         std::span<const std::array<int, 3>> triangles,
                         std::span<const DataArray> point_data,
                         std::span<const DataArray> cell_data, VtuCompression compression = {});

// Polygons (VTK_POLYGON = 7), each with its own vertices (at least 3); cell_data one tuple per
// polygon. Same validation as above.
void write_vtu_polygons(const std::filesystem::path& path,
                        std::span<const std::vector<geometry::Point>> polygons,
                        std::span<const DataArray> cell_data, VtuCompression compression = {});

// Line segments (VTK_LINE = 3), each with its own two end points; cell_data one tuple per
// segment. Same validation as above.
void write_vtu_segments(const std::filesystem::path& path,
                        std::span<const std::array<geometry::Point, 2>> segments,
                        std::span<const DataArray> cell_data, VtuCompression compression = {});

// `text` with &, <, >, " and ' replaced by XML entities, for attribute values.
std::string escape_xml(std::string_view text);

}  // namespace hydrodda::output
