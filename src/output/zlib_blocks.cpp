#include "output/zlib_blocks.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <exception>
#include <optional>
#include <stdexcept>

#include "numerics/parallel.hpp"

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

// One deflate state reused (deflateReset) for every block a thread compresses: a fresh
// deflateInit per 32 KiB block would allocate and clear its 256 KiB of tables each time.
class Deflater {
 public:
  explicit Deflater(int level) {
    if (deflateInit(&stream_, level) != Z_OK) throw std::runtime_error("zlib: deflateInit failed");
  }
  ~Deflater() { deflateEnd(&stream_); }
  Deflater(const Deflater&) = delete;
  Deflater& operator=(const Deflater&) = delete;

  // `block` as one complete zlib stream.
  std::string compress(std::span<const std::byte> block) {
    deflateReset(&stream_);
    std::string out(deflateBound(&stream_, static_cast<uLong>(block.size())), '\0');
    stream_.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(block.data()));
    stream_.avail_in = static_cast<uInt>(block.size());
    stream_.next_out = reinterpret_cast<Bytef*>(out.data());
    stream_.avail_out = static_cast<uInt>(out.size());
    if (deflate(&stream_, Z_FINISH) != Z_STREAM_END) throw std::runtime_error("zlib: deflate failed");
    out.resize(out.size() - stream_.avail_out);
    return out;
  }

 private:
  z_stream stream_{};
};

std::size_t block_count(std::size_t bytes) { return (bytes + zlib_block_size - 1) / zlib_block_size; }

}  // namespace

std::size_t ZlibEncoding::size() const {
  std::size_t n = header.size();
  for (const std::string& b : blocks) n += b.size();
  return n;
}

std::string ZlibEncoding::joined() const {
  std::string out;
  out.reserve(size());
  out += header;
  for (const std::string& b : blocks) out += b;
  return out;
}

std::vector<ZlibEncoding> compress_zlib_blocks(std::span<const std::span<const std::byte>> arrays, int level) {
  if (level < 0 || level > 9) {
    throw std::invalid_argument(fmt::format("zlib compression level {}: need 0 to 9", level));
  }
  struct Block {
    std::size_t array;
    std::span<const std::byte> bytes;
  };
  std::vector<Block> blocks;
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    for (std::size_t first = 0; first < arrays[a].size(); first += zlib_block_size) {
      blocks.push_back({a, arrays[a].subspan(first, std::min(zlib_block_size, arrays[a].size() - first))});
    }
  }

  std::vector<std::string> compressed(blocks.size());
  std::exception_ptr failure;
  const auto count = static_cast<std::ptrdiff_t>(blocks.size());
#pragma omp parallel if (count > 2) num_threads(numerics::thread_count())
  {
    std::optional<Deflater> deflater;  // one per thread, made on its first block
#pragma omp for schedule(dynamic)
    for (std::ptrdiff_t b = 0; b < count; ++b) {
      try {
        if (!deflater) deflater.emplace(level);
        compressed[b] = deflater->compress(blocks[b].bytes);
      } catch (...) {
#pragma omp critical(zlib_blocks_failure)
        if (!failure) failure = std::current_exception();
      }
    }
  }
  if (failure) std::rethrow_exception(failure);

  std::vector<ZlibEncoding> encoded(arrays.size());
  std::size_t next = 0;  // blocks are in array order
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    const std::size_t own = block_count(arrays[a].size());
    std::string& header = encoded[a].header;
    header.resize((3 + own) * word);
    put_word(header, 0, own);
    put_word(header, word, zlib_block_size);
    put_word(header, 2 * word, arrays[a].size() % zlib_block_size);
    for (std::size_t b = 0; b < own; ++b) {
      put_word(header, (3 + b) * word, compressed[next + b].size());
      encoded[a].blocks.push_back(std::move(compressed[next + b]));
    }
    next += own;
  }
  return encoded;
}

std::uint32_t crc32_of(std::span<const std::byte> data, std::uint32_t previous) {
  uLong crc = previous;
  // zlib takes lengths as uInt: a file past 4 GiB goes in pieces.
  constexpr std::size_t kPiece = std::size_t{1} << 30;
  for (std::size_t at = 0; at < data.size(); at += kPiece) {
    const std::size_t n = std::min(kPiece, data.size() - at);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(data.data() + at), static_cast<uInt>(n));
  }
  return static_cast<std::uint32_t>(crc);
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
