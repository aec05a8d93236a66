#pragma once
// Our own reading of a .vtu file's appended arrays, for tests that check values without VTK:
// each <DataArray> element's attributes and its bytes, inflated from VTK's compressed blocks
// (output/zlib_blocks.hpp) at the offset the element names after the underscore.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "output/zlib_blocks.hpp"

namespace hydrodda::testing {

struct AppendedArray {
  std::string type, name;
  int components = 0;
  std::string bytes;
};

inline std::string read_file_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every array of the file's text, in the order of their elements.
inline std::vector<AppendedArray> decode_appended(const std::string& file) {
  std::vector<AppendedArray> arrays;
  const std::size_t data = file.find("<AppendedData encoding=\"raw\">");
  EXPECT_NE(data, std::string::npos) << "no raw appended data";
  if (data == std::string::npos) return arrays;
  const std::size_t start = file.find('_', data) + 1;
  const std::string xml = file.substr(0, data);
  for (std::size_t at = xml.find("<DataArray "); at != std::string::npos; at = xml.find("<DataArray ", at + 1)) {
    const std::string element = xml.substr(at, xml.find("/>", at) - at);
    const auto attribute = [&](const std::string& key) {
      const std::size_t begin = element.find(key + "=\"") + key.size() + 2;
      return element.substr(begin, element.find('"', begin) - begin);
    };
    EXPECT_EQ(attribute("format"), "appended") << element;
    const std::size_t offset = std::stoul(attribute("offset"));
    std::size_t consumed = 0;
    const auto encoded = std::as_bytes(std::span(file)).subspan(start + offset);
    arrays.push_back({attribute("type"), attribute("Name"), std::stoi(attribute("NumberOfComponents")),
                      output::inflate_zlib_blocks(encoded, consumed)});
  }
  return arrays;
}

template <class T>
std::vector<T> values_of(const std::string& bytes) {
  std::vector<T> values(bytes.size() / sizeof(T));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

// The values of the named Float64 array of the file's text; empty when there is none.
inline std::vector<double> read_vtu_array(const std::string& file, const std::string& name) {
  for (const AppendedArray& a : decode_appended(file)) {
    if (a.name == name) {
      EXPECT_EQ(a.type, "Float64") << name;
      return values_of<double>(a.bytes);
    }
  }
  return {};
}

// The values of the named Int64 array (a cell's connectivity, offsets); empty when there is none.
inline std::vector<std::int64_t> read_vtu_int64_array(const std::string& file, const std::string& name) {
  for (const AppendedArray& a : decode_appended(file)) {
    if (a.name == name) {
      EXPECT_EQ(a.type, "Int64") << name;
      return values_of<std::int64_t>(a.bytes);
    }
  }
  return {};
}

}  // namespace hydrodda::testing
