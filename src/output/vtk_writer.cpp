#include "output/vtk_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <set>
#include <stdexcept>

#include "output/atomic_file.hpp"

namespace hydrodda::output {
namespace {

using geometry::Point;

constexpr int vtk_line = 3;
constexpr int vtk_triangle = 5;
constexpr int vtk_polygon = 7;

// Cells in VTK's flat layout: all node indices, then the end offset of each cell.
struct CellBlock {
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  int type = 0;
};

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

void check_arrays(std::span<const DataArray> arrays, std::size_t count, const char* where) {
  std::set<std::string> names;
  for (const DataArray& a : arrays) {
    require(!a.name.empty(), fmt::format("VTK {} array with an empty name", where));
    require(names.insert(a.name).second,
            fmt::format("VTK {} array '{}' appears twice", where, a.name));
    require(a.components >= 1,
            fmt::format("VTK {} array '{}' has {} components; need at least 1", where, a.name,
                        a.components));
    const std::size_t expected = count * static_cast<std::size_t>(a.components);
    require(a.values.size() == expected,
            fmt::format("VTK {} array '{}' has {} values; expected {} ({} tuples x {} "
                        "components)",
                        where, a.name, a.values.size(), expected, count, a.components));
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      require(std::isfinite(a.values[i]),
              fmt::format("VTK {} array '{}' has a non-finite value at index {}", where, a.name,
                          i));
    }
  }
}

void check_points(std::span<const Point> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    require(std::isfinite(points[i].x) && std::isfinite(points[i].y),
            fmt::format("VTK point {} has a non-finite coordinate", i));
  }
}

using Out = std::back_insert_iterator<std::string>;

// "{:.17g}": 17 significant digits are enough for every double to read back to itself.
void write_data_array(std::string& out, const DataArray& a) {
  const int written = a.components == 2 ? 3 : a.components;
  fmt::format_to(Out(out),
                 "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"ascii\">\n",
                 escape_xml(a.name), written);
  const std::size_t c = static_cast<std::size_t>(a.components);
  for (std::size_t t = 0; t * c < a.values.size(); ++t) {
    out += "         ";
    for (std::size_t k = 0; k < c; ++k) fmt::format_to(Out(out), " {:.17g}", a.values[t * c + k]);
    if (a.components == 2) out += " 0";
    out += '\n';
  }
  out += "        </DataArray>\n";
}

void write_field_section(std::string& out, const char* tag, std::span<const DataArray> arrays) {
  fmt::format_to(Out(out), "      <{}>\n", tag);
  for (const DataArray& a : arrays) write_data_array(out, a);
  fmt::format_to(Out(out), "      </{}>\n", tag);
}

void write_int_array(std::string& out, const char* type, const char* name,
                     const std::vector<std::int64_t>& values) {
  fmt::format_to(Out(out), "        <DataArray type=\"{}\" Name=\"{}\" format=\"ascii\">\n", type,
                 name);
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += i % 12 == 0 ? "          " : " ";
    fmt::format_to(Out(out), "{}", values[i]);
    if (i % 12 == 11 || i + 1 == values.size()) out += '\n';
  }
  out += "        </DataArray>\n";
}

// Validates everything, then renders one <UnstructuredGrid> piece and writes it atomically.
void write_unstructured_grid(const std::filesystem::path& path, std::span<const Point> points,
                             const CellBlock& cells, std::span<const DataArray> point_data,
                             std::span<const DataArray> cell_data) {
  check_points(points);
  check_arrays(point_data, points.size(), "point");
  check_arrays(cell_data, cells.offsets.size(), "cell");

  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n";
  out += "  <UnstructuredGrid>\n";
  fmt::format_to(Out(out), "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 points.size(), cells.offsets.size());
  write_field_section(out, "PointData", point_data);
  write_field_section(out, "CellData", cell_data);
  out += "      <Points>\n";
  out += "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (const Point& p : points) fmt::format_to(Out(out), "          {:.17g} {:.17g} 0\n", p.x, p.y);
  out += "        </DataArray>\n";
  out += "      </Points>\n";
  out += "      <Cells>\n";
  write_int_array(out, "Int64", "connectivity", cells.connectivity);
  write_int_array(out, "Int64", "offsets", cells.offsets);
  const std::vector<std::int64_t> types(cells.offsets.size(), cells.type);
  write_int_array(out, "UInt8", "types", types);
  out += "      </Cells>\n";
  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
  write_file_atomically(path, out);
}

}  // namespace

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

void write_vtu_triangles(const std::filesystem::path& path, std::span<const Point> nodes,
                         std::span<const std::array<int, 3>> triangles,
                         std::span<const DataArray> point_data,
                         std::span<const DataArray> cell_data) {
  CellBlock cells;
  cells.type = vtk_triangle;
  cells.connectivity.reserve(3 * triangles.size());
  cells.offsets.reserve(triangles.size());
  const auto node_count = static_cast<std::int64_t>(nodes.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int n : triangles[t]) {
      require(n >= 0 && n < node_count,
              fmt::format("VTK triangle {} refers to node {}, outside 0..{}", t, n,
                          node_count - 1));
      cells.connectivity.push_back(n);
    }
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
  }
  write_unstructured_grid(path, nodes, cells, point_data, cell_data);
}

void write_vtu_polygons(const std::filesystem::path& path,
                        std::span<const std::vector<Point>> polygons,
                        std::span<const DataArray> cell_data) {
  CellBlock cells;
  cells.type = vtk_polygon;
  std::vector<Point> points;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    require(polygons[k].size() >= 3,
            fmt::format("VTK polygon {} has {} vertices; need at least 3", k,
                        polygons[k].size()));
    for (const Point& p : polygons[k]) {
      cells.connectivity.push_back(static_cast<std::int64_t>(points.size()));
      points.push_back(p);
    }
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
  }
  write_unstructured_grid(path, points, cells, {}, cell_data);
}

void write_vtu_segments(const std::filesystem::path& path,
                        std::span<const std::array<Point, 2>> segments,
                        std::span<const DataArray> cell_data) {
  CellBlock cells;
  cells.type = vtk_line;
  std::vector<Point> points;
  points.reserve(2 * segments.size());
  for (const auto& s : segments) {
    for (const Point& p : s) {
      cells.connectivity.push_back(static_cast<std::int64_t>(points.size()));
      points.push_back(p);
    }
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
  }
  write_unstructured_grid(path, points, cells, {}, cell_data);
}

}  // namespace hydrodda::output
