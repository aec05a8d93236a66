// VTK's compressed-block layout (zlib_blocks.hpp): the header words, and bytes that come back
// exactly through our decoder, for sizes around the 32 KiB block and every zlib level.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/zlib_blocks.hpp"

namespace hydrodda::output {
namespace {

std::uint64_t word_at(const std::string& data, std::size_t index) {
  std::uint64_t value = 0;
  std::memcpy(&value, data.data() + 8 * index, 8);
  return value;
}

// Bytes that compress a little, as a field's doubles do: a smooth sequence with noisy low bits.
std::string sample(std::size_t size) {
  std::string bytes(size, '\0');
  std::uint32_t state = 12345;
  for (std::size_t i = 0; i < size; ++i) {
    state = state * 1664525u + 1013904223u;
    bytes[i] = static_cast<char>(i % 8 < 4 ? state >> 24 : (i / 64) & 0xff);
  }
  return bytes;
}

std::span<const std::byte> as_bytes(const std::string& s) { return std::as_bytes(std::span(s)); }

std::string encode(std::span<const std::byte> bytes, int level) {
  const std::vector<std::span<const std::byte>> arrays{bytes};
  return compress_zlib_blocks(arrays, level).at(0).joined();
}

TEST(ZlibBlocks, HeaderAndRoundTripAroundTheBlockSize) {
  constexpr std::size_t block = zlib_block_size;
  for (std::size_t size : {std::size_t{0}, std::size_t{1}, block - 1, block, block + 1, 3 * block, 100000 + std::size_t{3}}) {
    for (int level = 0; level <= 9; ++level) {
      const std::string input = sample(size);
      const std::string encoded = encode(as_bytes(input), level);
      const std::uint64_t blocks = (size + block - 1) / block;
      ASSERT_EQ(word_at(encoded, 0), blocks) << size;
      ASSERT_EQ(word_at(encoded, 1), block);
      ASSERT_EQ(word_at(encoded, 2), size % block) << "a full last block is written as 0";
      std::uint64_t total = (3 + blocks) * 8;
      for (std::uint64_t b = 0; b < blocks; ++b) total += word_at(encoded, 3 + b);
      ASSERT_EQ(total, encoded.size()) << "the header's sizes account for every byte";
      std::size_t consumed = 0;
      ASSERT_EQ(inflate_zlib_blocks(as_bytes(encoded + "trailing"), consumed), input) << size << " " << level;
      ASSERT_EQ(consumed, encoded.size());
    }
  }
}

// The blocks of many arrays are compressed on several threads: each array's encoding is the
// one it has alone, in the arrays' order.
TEST(ZlibBlocks, ManyArraysAtOnceAsEachAlone) {
  std::vector<std::string> inputs;
  for (std::size_t size : {std::size_t{70000}, std::size_t{0}, std::size_t{5}, std::size_t{200000}, std::size_t{32768}})
    inputs.push_back(sample(size) + std::to_string(size));
  std::vector<std::span<const std::byte>> arrays;
  for (const std::string& input : inputs) arrays.push_back(as_bytes(input));
  const std::vector<ZlibEncoding> together = compress_zlib_blocks(arrays, 1);
  ASSERT_EQ(together.size(), inputs.size());
  for (std::size_t a = 0; a < inputs.size(); ++a) {
    EXPECT_EQ(together[a].joined(), encode(arrays[a], 1)) << "array " << a;
    std::size_t consumed = 0;
    EXPECT_EQ(inflate_zlib_blocks(as_bytes(together[a].joined()), consumed), inputs[a]) << "array " << a;
  }
}

TEST(ZlibBlocks, CompressesRepeatedValues) {
  const std::vector<double> matrix_permeability(100000, 9.69e-18);
  EXPECT_LT(encode(std::as_bytes(std::span(matrix_permeability)), 1).size(), 800000u / 100);
}

TEST(ZlibBlocks, RejectsBadLevelsAndDamagedData) {
  const std::string input = sample(50000);
  EXPECT_THROW(encode(as_bytes(input), -1), std::invalid_argument);
  EXPECT_THROW(encode(as_bytes(input), 10), std::invalid_argument);
  const std::string out = encode(as_bytes(input), 6);
  std::size_t consumed = 0;
  EXPECT_THROW(inflate_zlib_blocks(as_bytes(out.substr(0, out.size() - 10)), consumed), std::runtime_error);
  std::string damaged = out;
  damaged[5 * 8 + 20] ^= 0x5a;  // inside the first block's stream
  EXPECT_THROW(inflate_zlib_blocks(as_bytes(damaged), consumed), std::runtime_error);
  EXPECT_THROW(inflate_zlib_blocks(as_bytes(out.substr(0, 12)), consumed), std::runtime_error);
}

}  // namespace
}  // namespace hydrodda::output
