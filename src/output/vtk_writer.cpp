#include "output/vtk_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <set>
#include <stdexcept>
#include <utility>

#include "output/atomic_file.hpp"
#include "output/zlib_blocks.hpp"

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

// The message is formatted only on failure: these checks run once per value and node.
template <class... Args>
void require(bool ok, fmt::format_string<Args...> message, Args&&... args) {
  if (!ok) throw std::invalid_argument(fmt::format(message, std::forward<Args>(args)...));
}

void check_arrays(std::span<const DataArray> arrays, std::size_t count, const char* where) {
  std::set<std::string> names;
  for (const DataArray& a : arrays) {
    require(!a.name.empty(), "VTK {} array with an empty name", where);
    require(names.insert(a.name).second, "VTK {} array '{}' appears twice", where, a.name);
    require(a.components >= 1, "VTK {} array '{}' has {} components; need at least 1", where,
            a.name, a.components);
    const std::size_t expected = count * static_cast<std::size_t>(a.components);
    require(a.values.size() == expected,
            "VTK {} array '{}' has {} values; expected {} ({} tuples x {} components)", where,
            a.name, a.values.size(), expected, count, a.components);
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      require(std::isfinite(a.values[i]), "VTK {} array '{}' has a non-finite value at index {}",
              where, a.name, i);
    }
  }
}

void check_points(std::span<const Point> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    require(std::isfinite(points[i].x) && std::isfinite(points[i].y),
            "VTK point {} has a non-finite coordinate", i);
  }
}

using Out = std::back_insert_iterator<std::string>;

// (x, y) pairs as (x, y, 0) triples: VTK's points have three coordinates, and ParaView treats
// a 3-component array as a vector (glyphs, stream lines, magnitude).
template <class XY>
std::vector<double> with_zero_z(std::size_t count, XY xy) {
  std::vector<double> xyz;
  xyz.reserve(3 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto [x, y] = xy(i);
    xyz.insert(xyz.end(), {x, y, 0.0});
  }
  return xyz;
}

// One <DataArray> of a file and the bytes it stores.
struct Array {
  std::string_view type;
  std::string_view name;
  int components;
  std::span<const std::byte> bytes;
};

// The arrays of one XML element of the piece (<PointData>, <CellData>, <Points>, <Cells>).
struct Section {
  const char* tag;
  std::vector<Array> arrays;
};

// A field's array; a 2-component field's (x, y, 0) triples are kept in `padded`.
Array field_array(const DataArray& a, std::vector<std::vector<double>>& padded) {
  if (a.components != 2) return {"Float64", a.name, a.components, std::as_bytes(std::span(a.values))};
  const auto& v = a.values;
  padded.push_back(with_zero_z(v.size() / 2, [&](std::size_t t) { return std::pair{v[2 * t], v[2 * t + 1]}; }));
  return {"Float64", a.name, 3, std::as_bytes(std::span(padded.back()))};
}

// The whole file: the XML, each array's element naming its offset into the appended data, then
// the appended data after an underscore, which marks where the raw bytes begin.
std::string render_file(std::size_t point_count, std::size_t cell_count, std::span<const Section> sections,
                        int level) {
  std::vector<std::span<const std::byte>> bytes;
  for (const Section& s : sections)
    for (const Array& a : s.arrays) bytes.push_back(a.bytes);
  const std::vector<std::string> encoded = compress_zlib_blocks(bytes, level);

  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n";
  xml += "  <UnstructuredGrid>\n";
  fmt::format_to(Out(xml), "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", point_count, cell_count);
  std::size_t index = 0, offset = 0;
  for (const Section& s : sections) {
    fmt::format_to(Out(xml), "      <{}>\n", s.tag);
    for (const Array& a : s.arrays) {
      fmt::format_to(Out(xml),
                     "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                     "format=\"appended\" offset=\"{}\"/>\n",
                     a.type, escape_xml(a.name), a.components, offset);
      offset += encoded[index++].size();
    }
    fmt::format_to(Out(xml), "      </{}>\n", s.tag);
  }
  xml += "    </Piece>\n";
  xml += "  </UnstructuredGrid>\n";
  xml += "  <AppendedData encoding=\"raw\">\n   _";
  xml.reserve(xml.size() + offset + 32);
  for (const std::string& e : encoded) xml += e;
  xml += "\n  </AppendedData>\n";
  xml += "</VTKFile>\n";
  return xml;
}

// Validates everything, then renders one <UnstructuredGrid> piece and writes it atomically.
void write_unstructured_grid(const std::filesystem::path& path, std::span<const Point> points,
                             const CellBlock& cells, std::span<const DataArray> point_data,
                             std::span<const DataArray> cell_data, VtuCompression compression) {
  check_points(points);
  check_arrays(point_data, points.size(), "point");
  check_arrays(cell_data, cells.offsets.size(), "cell");

  std::vector<std::vector<double>> padded;
  padded.reserve(point_data.size() + cell_data.size());  // the spans into it stay valid
  std::vector<Section> sections{{"PointData", {}}, {"CellData", {}}};
  for (const DataArray& a : point_data) sections[0].arrays.push_back(field_array(a, padded));
  for (const DataArray& a : cell_data) sections[1].arrays.push_back(field_array(a, padded));
  const auto xyz = with_zero_z(points.size(), [&](std::size_t i) { return std::pair{points[i].x, points[i].y}; });
  sections.push_back({"Points", {{"Float64", "Points", 3, std::as_bytes(std::span(xyz))}}});
  const std::vector<std::uint8_t> types(cells.offsets.size(), static_cast<std::uint8_t>(cells.type));
  sections.push_back({"Cells",
                      {{"Int64", "connectivity", 1, std::as_bytes(std::span(cells.connectivity))},
                       {"Int64", "offsets", 1, std::as_bytes(std::span(cells.offsets))},
                       {"UInt8", "types", 1, std::as_bytes(std::span(types))}}});
  write_file_atomically(path, render_file(points.size(), cells.offsets.size(), sections, compression.level));
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
                         std::span<const DataArray> cell_data, VtuCompression compression) {
  CellBlock cells;
  cells.type = vtk_triangle;
  cells.connectivity.reserve(3 * triangles.size());
  cells.offsets.reserve(triangles.size());
  const auto node_count = static_cast<std::int64_t>(nodes.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int n : triangles[t]) {
      require(n >= 0 && n < node_count, "VTK triangle {} refers to node {}, outside 0..{}", t, n,
              node_count - 1);
      cells.connectivity.push_back(n);
    }
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
  }
  write_unstructured_grid(path, nodes, cells, point_data, cell_data, compression);
}

void write_vtu_polygons(const std::filesystem::path& path,
                        std::span<const std::vector<Point>> polygons,
                        std::span<const DataArray> cell_data, VtuCompression compression) {
  CellBlock cells;
  cells.type = vtk_polygon;
  std::vector<Point> points;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    require(polygons[k].size() >= 3, "VTK polygon {} has {} vertices; need at least 3", k,
            polygons[k].size());
    for (const Point& p : polygons[k]) {
      cells.connectivity.push_back(static_cast<std::int64_t>(points.size()));
      points.push_back(p);
    }
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
  }
  write_unstructured_grid(path, points, cells, {}, cell_data, compression);
}

void write_vtu_segments(const std::filesystem::path& path,
                        std::span<const std::array<Point, 2>> segments,
                        std::span<const DataArray> cell_data, VtuCompression compression) {
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
  write_unstructured_grid(path, points, cells, {}, cell_data, compression);
}

}  // namespace hydrodda::output
