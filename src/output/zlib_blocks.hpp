#pragma once
// Binary data compressed as VTK's XML files store it (vtkZLibDataCompressor with
// header_type="UInt64"): the bytes cut into blocks of `zlib_block_size`, each a zlib stream of
// its own, behind a header of little-endian UInt64 words
//   [block count, block size, size of a partial last block (0 when it is full),
//    compressed size of block 0, of block 1, ...].
// Also zlib's CRC-32, the checkpoint's checksum. The only file of ours that includes zlib
// (Debian's zlib1g).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hydrodda::output {

// VTK's default block size, so the files are laid out as ParaView's own.
inline constexpr std::size_t zlib_block_size = 32768;

// One array's encoding: its header, then its compressed blocks, kept apart so that a writer
// can write them one after another (joining them would hold the encoding twice).
struct ZlibEncoding {
  std::string header;
  std::vector<std::string> blocks;
  std::size_t size() const;
  std::string joined() const;  // header and blocks in one string
};

// Each array's encoding. `level` is zlib's, 0 (stored, no
// compression) to 9 (smallest); throws std::invalid_argument outside that range and
// std::runtime_error if zlib fails. The blocks of all the arrays are shared among the OpenMP
// threads: a file's arrays are many and small (a contact file of the 1,601-block wall: nine
// of 9–450 kB), so sharing arrays instead would leave a thread idle.
std::vector<ZlibEncoding> compress_zlib_blocks(std::span<const std::span<const std::byte>> arrays, int level);

// The inverse for one array, for tests and tools: the bytes of the encoding that starts at
// `data` (header first); `consumed` is set to the number of bytes it took. Throws
// std::runtime_error on a truncated or corrupt encoding.
std::string inflate_zlib_blocks(std::span<const std::byte> data, std::size_t& consumed);

// The CRC-32 (ISO 3309, zlib's crc32) of `data`, continuing `crc`, that of the bytes before it.
std::uint32_t crc32_of(std::span<const std::byte> data, std::uint32_t crc = 0);

}  // namespace hydrodda::output
