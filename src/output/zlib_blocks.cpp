#include "output/zlib_blocks.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <stdexcept>

namespace hydrodda::output {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the VTK files declare byte_order=\"LittleEndian\" and are written from memory");

constexpr std::size_t word = sizeof(std::uint64_t);

void put_word(std::string& out, std::size_t at, std::uint64_t value) {
  std::memcpy(out.data() + at, &value, word);
}

std::uint64_t get_word(std::span<const std::byte> data, std::size_t at) {
  if (at + word > data.size()) throw std::runtime_error("compressed VTK data: truncated header");
  std::uint64_t value = 0;
  std::memcpy(&value, data.data() + at, word);
  return value;
}

// One deflate state reused (deflateReset) for every block: a fresh deflateInit per 32 KiB block
// would allocate and clear its 256 KiB of tables each time.
class Deflater {
 public:
  explicit Deflater(int level) {
    if (deflateInit(&stream_, level) != Z_OK) throw std::runtime_error("zlib: deflateInit failed");
  }
  ~Deflater() { deflateEnd(&stream_); }
  Deflater(const Deflater&) = delete;
  Deflater& operator=(const Deflater&) = delete;

  // Appends `block` as one complete zlib stream; returns its compressed size.
  std::size_t append(std::string& out, std::span<const std::byte> block) {
    deflateReset(&stream_);
    const std::size_t at = out.size();
    const auto bound = deflateBound(&stream_, static_cast<uLong>(block.size()));
    out.resize(at + bound);
    stream_.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(block.data()));
    stream_.avail_in = static_cast<uInt>(block.size());
    stream_.next_out = reinterpret_cast<Bytef*>(out.data() + at);
    stream_.avail_out = static_cast<uInt>(bound);
    if (deflate(&stream_, Z_FINISH) != Z_STREAM_END) throw std::runtime_error("zlib: deflate failed");
    const std::size_t size = bound - stream_.avail_out;
    out.resize(at + size);
    return size;
  }

 private:
  z_stream stream_{};
};

}  // namespace

void append_zlib_blocks(std::string& out, std::span<const std::byte> bytes, int level) {
  if (level < 0 || level > 9) {
    throw std::invalid_argument(fmt::format("zlib compression level {}: need 0 to 9", level));
  }
  const std::size_t blocks = (bytes.size() + zlib_block_size - 1) / zlib_block_size;
  const std::size_t header_at = out.size();
  out.resize(header_at + (3 + blocks) * word);
  put_word(out, header_at, blocks);
  put_word(out, header_at + word, zlib_block_size);
  put_word(out, header_at + 2 * word, bytes.size() % zlib_block_size);
  if (blocks == 0) return;
  Deflater deflater(level);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t first = b * zlib_block_size;
    const std::size_t size = std::min(zlib_block_size, bytes.size() - first);
    put_word(out, header_at + (3 + b) * word, deflater.append(out, bytes.subspan(first, size)));
  }
}

std::string inflate_zlib_blocks(std::span<const std::byte> data, std::size_t& consumed) {
  const std::uint64_t blocks = get_word(data, 0);
  const std::uint64_t block_size = get_word(data, word);
  const std::uint64_t last_size = get_word(data, 2 * word);
  if (blocks > data.size() / word || block_size == 0 || last_size >= block_size) {
    throw std::runtime_error(fmt::format("compressed VTK data: bad header ({} blocks of {}, last {})",
                                         blocks, block_size, last_size));
  }
  std::size_t at = (3 + blocks) * word;
  std::string bytes;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressed = get_word(data, (3 + b) * word);
    const std::uint64_t expected = b + 1 == blocks && last_size != 0 ? last_size : block_size;
    if (compressed > data.size() - at) throw std::runtime_error("compressed VTK data: truncated block");
    const std::size_t begin = bytes.size();
    bytes.resize(begin + expected);
    uLongf size = static_cast<uLongf>(expected);
    const int status = uncompress(reinterpret_cast<Bytef*>(bytes.data() + begin), &size,
                                  reinterpret_cast<const Bytef*>(data.data() + at),
                                  static_cast<uLong>(compressed));
    if (status != Z_OK || size != expected) {
      throw std::runtime_error(fmt::format("compressed VTK data: block {} does not inflate to {} bytes", b,
                                           expected));
    }
    at += compressed;
  }
  consumed = at;
  return bytes;
}

}  // namespace hydrodda::output
