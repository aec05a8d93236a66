// hydrodda_order: METIS_NodeND of one graph, a helper process of numerics/nested_dissection.cpp.
// METIS cannot order two graphs at once in one process (its random number generator is
// shared), and a forked copy of a large process pays for the memory it then shares; this small
// program orders one half of the flow matrix's graph beside the program, which orders the other.
//
// Reads from standard input: n and the edge count (two int64), then METIS's xadj (n + 1 idx_t)
// and adjncy (edge-count idx_t); writes the order (n idx_t) to standard output. Exit status 0
// when it did, 1 otherwise.
#include <metis.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <vector>

namespace {

// Moves exactly `size` bytes through `io` (a read or a write), retrying interrupted calls;
// false at the end of the input or on an error.
template <class Io>
bool transfer_exactly(Io io, char* bytes, std::size_t size) {
  while (size > 0) {
    const ssize_t n = io(bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool read_exactly(void* data, std::size_t size) {
  return transfer_exactly([](char* b, std::size_t n) { return ::read(0, b, n); }, static_cast<char*>(data), size);
}

bool write_exactly(const void* data, std::size_t size) {
  return transfer_exactly([](char* b, std::size_t n) { return ::write(1, b, n); },
                          const_cast<char*>(static_cast<const char*>(data)), size);
}

}  // namespace

int main() {
  std::int64_t header[2];
  if (!read_exactly(header, sizeof header) || header[0] <= 0 || header[1] < 0) return 1;
  idx_t n = static_cast<idx_t>(header[0]);
  std::vector<idx_t> xadj(n + 1), adjncy(static_cast<std::size_t>(header[1]));
  if (!read_exactly(xadj.data(), xadj.size() * sizeof(idx_t)) ||
      !read_exactly(adjncy.data(), adjncy.size() * sizeof(idx_t)))
    return 1;
  std::vector<idx_t> order(n), inverse(n);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  if (METIS_NodeND(&n, xadj.data(), adjncy.data(), nullptr, options, order.data(), inverse.data()) != METIS_OK)
    return 1;
  return write_exactly(order.data(), order.size() * sizeof(idx_t)) ? 0 : 1;
}
