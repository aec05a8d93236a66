#include "output/vtk_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <memory>
#include <numeric>
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
    const std::span<const double> values = a.numbers();
    const std::size_t expected = count * static_cast<std::size_t>(a.components);
    require(values.size() == expected,
            "VTK {} array '{}' has {} values; expected {} ({} tuples x {} components)", where,
            a.name, values.size(), expected, count, a.components);
    for (std::size_t i = 0; i < values.size(); ++i) {
      require(std::isfinite(values[i]), "VTK {} array '{}' has a non-finite value at index {}",
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

// The bytes of an array made for the file, kept alive by `owner` until they are compressed.
struct MadeBytes {
  std::shared_ptr<const void> owner;
  std::span<const std::byte> bytes;
};

template <class T>
MadeBytes bytes_of(std::vector<T> values) {
  auto owner = std::make_shared<const std::vector<T>>(std::move(values));
  return {owner, std::as_bytes(std::span(*owner))};
}

// One <DataArray> of a file: its bytes in place, or made only when it is compressed (points
// as triples, cells as 64-bit integers, a 2-component field padded), so that a file of a
// million triangles never holds all its arrays at once.
struct Array {
  std::string_view type;
  std::string_view name;
  int components;
  std::span<const std::byte> bytes;
  std::function<MadeBytes()> make;
};

// The arrays of one XML element of the piece (<PointData>, <CellData>, <Points>, <Cells>).
struct Section {
  const char* tag;
  std::vector<Array> arrays;
};

// A field's array; a 2-component field's (x, y, 0) triples are made when it is compressed.
Array field_array(const DataArray& a) {
  const std::span<const double> v = a.numbers();
  if (a.components != 2) return {"Float64", a.name, a.components, std::as_bytes(v), {}};
  return {"Float64", a.name, 3, {}, [v] {
            return bytes_of(with_zero_z(v.size() / 2, [&](std::size_t t) { return std::pair{v[2 * t], v[2 * t + 1]}; }));
          }};
}

// The XML before the appended data, each array's element naming its offset into that data.
// Each offset is padded with spaces to kOffsetWidth characters, so that the text written
// before the offsets are known has the length of the final one.
constexpr std::size_t kOffsetWidth = 20;  // the digits of the largest 64-bit offset
std::string render_header(std::size_t point_count, std::size_t cell_count, std::span<const Section> sections,
                          std::span<const std::size_t> sizes) {
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
      const std::string number = std::to_string(offset);
      fmt::format_to(Out(xml),
                     "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                     "format=\"appended\" offset=\"{}\"{:{}}/>\n",
                     a.type, escape_xml(a.name), a.components, number, "", kOffsetWidth - number.size() + 1);
      offset += index < sizes.size() ? sizes[index] : 0;
      ++index;
    }
    fmt::format_to(Out(xml), "      </{}>\n", s.tag);
  }
  xml += "    </Piece>\n";
  xml += "  </UnstructuredGrid>\n";
  xml += "  <AppendedData encoding=\"raw\">\n   _";
  return xml;
}

// The whole file, written as it is made: the XML (its offsets filled in last), then after an
// underscore, which marks where the raw bytes begin, each array's compressed encoding as its
// batch is done. Arrays are compressed in batches of about kBatchBytes: the OpenMP threads
// share the blocks of a batch's many small arrays (a contact file's), while the bytes made for
// a batch, and their encoding, are let go before the next is made.
void write_file(const std::filesystem::path& path, std::size_t point_count, std::size_t cell_count,
                std::span<const Section> sections, int level) {
  constexpr std::size_t kBatchBytes = std::size_t{16} << 20;
  AtomicFile file(path, Durability::atomic);  // a run's field: see RunFolder::durability_of
  const std::string placeholder = render_header(point_count, cell_count, sections, {});
  file.write(placeholder);
  std::vector<std::size_t> sizes;
  std::vector<MadeBytes> made;
  std::vector<std::span<const std::byte>> batch;
  std::size_t batch_bytes = 0;
  const auto flush = [&] {
    std::vector<ZlibEncoding> encoded = compress_zlib_blocks(batch, level);
    for (ZlibEncoding& array : encoded) {
      sizes.push_back(array.size());
      file.write(array.header);
      for (std::string& block : array.blocks) {
        file.write(block);
        std::string().swap(block);  // let go as written
      }
    }
    batch.clear();
    made.clear();
    batch_bytes = 0;
  };
  for (const Section& s : sections)
    for (const Array& a : s.arrays) {
      if (a.make) {
        made.push_back(a.make());
        batch.push_back(made.back().bytes);
      } else {
        batch.push_back(a.bytes);
      }
      batch_bytes += batch.back().size();
      if (batch_bytes >= kBatchBytes) flush();
    }
  if (!batch.empty()) flush();
  file.write("\n  </AppendedData>\n</VTKFile>\n");
  const std::string header = render_header(point_count, cell_count, sections, sizes);
  if (header.size() != placeholder.size()) throw std::logic_error("VTK header: offsets wider than reserved");
  file.write_at(0, header);
  file.commit();
}

// A piece's cells: their connectivity (all node indices) and the end offset of each, made
// when they are compressed.
struct CellArrays {
  std::size_t count = 0;
  int type = 0;
  std::function<MadeBytes()> connectivity;
  std::function<MadeBytes()> offsets;
};

// Validates everything, then writes one <UnstructuredGrid> piece atomically.
void write_unstructured_grid(const std::filesystem::path& path, std::span<const Point> points,
                             const CellArrays& cells, std::span<const DataArray> point_data,
                             std::span<const DataArray> cell_data, VtuCompression compression) {
  check_points(points);
  check_arrays(point_data, points.size(), "point");
  check_arrays(cell_data, cells.count, "cell");

  std::vector<Section> sections{{"PointData", {}}, {"CellData", {}}};
  for (const DataArray& a : point_data) sections[0].arrays.push_back(field_array(a));
  for (const DataArray& a : cell_data) sections[1].arrays.push_back(field_array(a));
  const auto xyz = [points] {
    return bytes_of(with_zero_z(points.size(), [&](std::size_t i) { return std::pair{points[i].x, points[i].y}; }));
  };
  sections.push_back({"Points", {{"Float64", "Points", 3, {}, xyz}}});
  const auto types = [&cells] {
    return bytes_of(std::vector<std::uint8_t>(cells.count, static_cast<std::uint8_t>(cells.type)));
  };
  sections.push_back({"Cells",
                      {{"Int64", "connectivity", 1, {}, cells.connectivity},
                       {"Int64", "offsets", 1, {}, cells.offsets},
                       {"UInt8", "types", 1, {}, types}}});
  write_file(path, points.size(), cells.count, sections, compression.level);
}

// Cells on points of their own, numbered in turn: connectivity 0, 1, 2, ... and each cell's
// end offset, the running sum of `corners_of` (the blocks' and segments' own points).
CellArrays numbered_cells(int type, std::size_t count, std::function<std::size_t(std::size_t)> corners_of) {
  CellArrays cells;
  cells.count = count;
  cells.type = type;
  std::vector<std::int64_t> offsets(count);
  std::int64_t end = 0;
  for (std::size_t k = 0; k < count; ++k) offsets[k] = end += static_cast<std::int64_t>(corners_of(k));
  cells.connectivity = [end] {
    std::vector<std::int64_t> connectivity(static_cast<std::size_t>(end));
    std::iota(connectivity.begin(), connectivity.end(), std::int64_t{0});
    return bytes_of(std::move(connectivity));
  };
  cells.offsets = [offsets = std::move(offsets)] { return bytes_of(offsets); };
  return cells;
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
  const auto node_count = static_cast<std::int64_t>(nodes.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int n : triangles[t])
      require(n >= 0 && n < node_count, "VTK triangle {} refers to node {}, outside 0..{}", t, n,
              node_count - 1);
  CellArrays cells;
  cells.count = triangles.size();
  cells.type = vtk_triangle;
  cells.connectivity = [triangles] {
    std::vector<std::int64_t> connectivity;
    connectivity.reserve(3 * triangles.size());
    for (const std::array<int, 3>& t : triangles) connectivity.insert(connectivity.end(), t.begin(), t.end());
    return bytes_of(std::move(connectivity));
  };
  cells.offsets = [triangles] {
    std::vector<std::int64_t> offsets(triangles.size());
    for (std::size_t t = 0; t < offsets.size(); ++t) offsets[t] = 3 * static_cast<std::int64_t>(t + 1);
    return bytes_of(std::move(offsets));
  };
  write_unstructured_grid(path, nodes, cells, point_data, cell_data, compression);
}

void write_vtu_polygons(const std::filesystem::path& path,
                        std::span<const std::vector<Point>> polygons,
                        std::span<const DataArray> cell_data, VtuCompression compression) {
  std::vector<Point> points;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    require(polygons[k].size() >= 3, "VTK polygon {} has {} vertices; need at least 3", k,
            polygons[k].size());
    points.insert(points.end(), polygons[k].begin(), polygons[k].end());
  }
  const CellArrays cells =
      numbered_cells(vtk_polygon, polygons.size(), [polygons](std::size_t k) { return polygons[k].size(); });
  write_unstructured_grid(path, points, cells, {}, cell_data, compression);
}

void write_vtu_segments(const std::filesystem::path& path,
                        std::span<const std::array<Point, 2>> segments,
                        std::span<const DataArray> cell_data, VtuCompression compression) {
  std::vector<Point> points;
  points.reserve(2 * segments.size());
  for (const auto& s : segments) points.insert(points.end(), s.begin(), s.end());
  const CellArrays cells = numbered_cells(vtk_line, segments.size(), [](std::size_t) { return std::size_t{2}; });
  write_unstructured_grid(path, points, cells, {}, cell_data, compression);
}

}  // namespace hydrodda::output
