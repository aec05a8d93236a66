#pragma once
// VTK XML unstructured-grid (.vtu) files for ParaView: the fluid mesh, the blocks and the
// contacts/fractures of one output step. Written by hand (ASCII, full double precision)
// because the product does not depend on the VTK library for a few hundred lines of XML.

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::output {

// One named field on points or cells: `values` holds count * components numbers, tuple by tuple.
// A 2-component field is written with 3 components (z = 0) so ParaView treats it as a vector.
struct DataArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

// Triangles (VTK_TRIANGLE = 5) on shared nodes (x, y; z = 0 is written); each triangle is
// three indices into `nodes`. point_data has one tuple per node, cell_data one per triangle.
// Throws std::invalid_argument (naming the array or triangle) on any size or index mismatch,
// empty or duplicate names, or non-finite numbers.
void write_vtu_triangles(const std::filesystem::path& path,
                         std::span<const geometry::Point> nodes,
                         std::span<const std::array<int, 3>> triangles,
                         std::span<const DataArray> point_data,
                         std::span<const DataArray> cell_data);

// Polygons (VTK_POLYGON = 7), each with its own vertices (at least 3); cell_data one tuple per
// polygon. Same validation as above.
void write_vtu_polygons(const std::filesystem::path& path,
                        std::span<const std::vector<geometry::Point>> polygons,
                        std::span<const DataArray> cell_data);

// Line segments (VTK_LINE = 3), each with its own two end points; cell_data one tuple per
// segment. Same validation as above.
void write_vtu_segments(const std::filesystem::path& path,
                        std::span<const std::array<geometry::Point, 2>> segments,
                        std::span<const DataArray> cell_data);

// `text` with &, <, >, " and ' replaced by XML entities, for attribute values.
std::string escape_xml(std::string_view text);

}  // namespace hydrodda::output
