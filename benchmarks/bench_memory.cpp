// What fresh memory costs on this machine: a fresh process's first DDA step touches some
// 30 MB for the first time (the factor, the contacts, the springs), and on a virtual machine
// the host may back each page only as it is first written. Each iteration maps 32 MiB of
// anonymous memory, writes one byte a page (the first touch, timed) and unmaps it, on
// ordinary 4 KiB pages or advised for transparent huge pages (what the programs' allocator
// asks for; src/allocator_options.cpp). Counter: milliseconds a mebibyte.

#include <sys/mman.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include <benchmark/benchmark.h>

namespace {

constexpr std::size_t kMebibyte = std::size_t{1} << 20;
constexpr std::size_t kTouched = 32 * kMebibyte;
constexpr std::size_t kHugePage = 2 * kMebibyte;
constexpr std::size_t kPage = 4096;

void BM_FirstTouch(benchmark::State& state) {
  const bool huge = state.range(0) == 1;
  double seconds = 0.0;
  for (auto _ : state) {
    // One huge page more than needed, to start on a huge-page boundary.
    const std::size_t mapped = kTouched + kHugePage;
    void* region = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (region == MAP_FAILED) throw std::runtime_error("bench_memory: mmap failed");
    const auto address = reinterpret_cast<std::uintptr_t>(region);
    auto* start = reinterpret_cast<volatile char*>((address + kHugePage - 1) & ~(kHugePage - 1));
    if (huge) madvise(const_cast<char*>(start), kTouched, MADV_HUGEPAGE);
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t offset = 0; offset < kTouched; offset += kPage) start[offset] = 1;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    seconds += elapsed;
    state.SetIterationTime(elapsed);
    munmap(region, mapped);
  }
  state.counters["ms_per_MiB"] = 1e3 * seconds / static_cast<double>(state.iterations()) / 32.0;
}
BENCHMARK(BM_FirstTouch)->Arg(0)->Arg(1)->Iterations(5)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
