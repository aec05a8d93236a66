#pragma once
// Binary data compressed as VTK's XML files store it (vtkZLibDataCompressor with
// header_type="UInt64"): the bytes cut into blocks of `zlib_block_size`, each a zlib stream of
// its own, behind a header of little-endian UInt64 words
//   [block count, block size, size of a partial last block (0 when it is full),
//    compressed size of block 0, of block 1, ...].
// The only file of ours that includes zlib (Debian's zlib1g).

#include <cstddef>
#include <span>
#include <string>

namespace hydrodda::output {

// VTK's default block size, so the files are laid out as ParaView's own.
inline constexpr std::size_t zlib_block_size = 32768;

// Appends the header and the compressed blocks of `bytes` to `out`. `level` is zlib's, 0 (stored,
// no compression) to 9 (smallest); throws std::invalid_argument outside that range and
// std::runtime_error if zlib fails.
void append_zlib_blocks(std::string& out, std::span<const std::byte> bytes, int level);

// The inverse, for tests and tools: the bytes of the block sequence that starts at `data`
// (header first); `consumed` is set to the number of bytes it took. Throws std::runtime_error
// on a truncated or corrupt sequence.
std::string inflate_zlib_blocks(std::span<const std::byte> data, std::size_t& consumed);

}  // namespace hydrodda::output
