#pragma once
// Work shared between the process's threads so that the answer never depends on how many
// there are. Two kinds of loop, and a helper for each:
// - loops whose every index (or fixed-size chunk of indices) writes only its own data, or whose
//   chunks' results combine in an order that cannot change the result (a count, a largest
//   value, an "any", lists joined in chunk order): for_each_index, for_each_chunk and
//   results_in_chunks, on as many threads as thread_count() allows. The chunks are of a size
//   fixed by the caller, never one per thread, so a chunk's work is the same on any machine;
// - work cut into two fixed parts whose results are summed, or an elimination tree's two
//   halves (the factorisations): run_two_parts, on at most two threads. The parts are the same
//   on one thread or eight, and so are the sums.
// Either way the threads only decide what runs side by side, never what is computed.

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <omp.h>

namespace hydrodda::numerics {

// The threads this process's parallel loops use: set_thread_count_of_this_thread's or
// set_thread_count's value; else OpenMP's count (OMP_NUM_THREADS or omp_set_num_threads, the
// benchmarks' and the tests' way to ask; by default the CPUs of the affinity mask), no more than
// the CPU quota allows unless OMP_NUM_THREADS asks for more: every core the process may run on
// (usable_core_count).
int thread_count();
// Sets thread_count() for every thread of the process (n ≥ 1; more than the cores is allowed:
// the threads then take turns). Throws std::invalid_argument below 1.
void set_thread_count(int n);
// Sets thread_count() for the loops this thread starts, over the process's (n ≥ 1), or takes
// that back (0): two runs on two threads of one process (Python's) each keep their own. Returns
// the value it replaces, for the caller to put back.
int set_thread_count_of_this_thread(int n);

// The cores this process may use: those of its CPU affinity mask (sched_getaffinity: taskset,
// a container's cpuset), no more than its cgroup's CPU quota allows (cpu.max, or cgroup v1's
// cpu.cfs_quota_us over cpu.cfs_period_us, rounded up), at least 1.
int usable_core_count();
// The cores a quota allows: a cgroup v2 cpu.max line ("max 100000", "150000 100000" → 2),
// or nothing for no quota or a line that cannot be read.
int cores_of_cpu_max(const std::string& line);

// Runs task(0) and task(1); on two threads if `parallel` (the caller's judgement that the
// parts are large enough to pay for waking a second thread) and two are allowed.
template <class Task>
void run_two_parts(bool parallel, Task&& task) {
  const int threads = parallel ? std::min(2, thread_count()) : 1;
  if (threads == 1) {  // not even a one-thread region: a small model's step has hundreds
    task(0);
    task(1);
    return;
  }
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int part = 0; part < 2; ++part) task(part);
}

// Whether run_two_parts(true, …) would use two threads.
inline bool two_threads_available() { return thread_count() >= 2; }

// Has the OpenMP runtime make its threads now, with the model, rather than inside the first
// step: a process's first parallel region takes from half a millisecond to ten on a virtual
// machine, the time to create the threads and to have the host run them.
void start_threads();

// Part `part` (0 or 1) of 0 … count − 1 split in halves: [first, second).
inline std::pair<std::size_t, std::size_t> half_range(int part, std::size_t count) {
  const std::size_t half = count / 2;
  if (part == 0) return {0, half};
  return {half, count};
}

// Chunks of `chunk` indices (the last one shorter) that 0 … count − 1 splits into.
inline std::size_t chunk_count(std::size_t count, std::size_t chunk) { return (count + chunk - 1) / chunk; }

// body(k, begin, end) for each chunk k = [begin, end) of `chunk` indices of 0 … count − 1,
// spread over the threads where `parallel`. Each chunk runs once, by the same code either way.
template <class Body>
void for_each_chunk(bool parallel, std::size_t count, std::size_t chunk, Body&& body) {
  const auto chunks = static_cast<std::ptrdiff_t>(chunk_count(count, chunk));
  const int threads = parallel ? static_cast<int>(std::min<std::ptrdiff_t>(thread_count(), chunks)) : 1;
  const auto run = [&](std::ptrdiff_t k) {
    const std::size_t begin = static_cast<std::size_t>(k) * chunk;
    body(static_cast<std::size_t>(k), begin, std::min(count, begin + chunk));
  };
  if (threads <= 1) {
    for (std::ptrdiff_t k = 0; k < chunks; ++k) run(k);
    return;
  }
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::ptrdiff_t k = 0; k < chunks; ++k) run(k);
}

// Indices per chunk of for_each_index: enough that a chunk outlasts its scheduling.
inline constexpr std::size_t kIndexChunk = 256;

// body(i) for every i in 0 … count − 1, over the threads where `parallel`. A body that writes
// only its own i's data gives the same answer on any number of threads.
template <class Body>
void for_each_index(bool parallel, std::size_t count, Body&& body) {
  for_each_chunk(parallel, count, kIndexChunk, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

// part(begin, end) over each chunk of `chunk` indices of 0 … count − 1, over the threads where
// `parallel`: the chunks' results in chunk order, for the caller to combine in that order.
template <class Part>
auto results_in_chunks(bool parallel, std::size_t count, std::size_t chunk, Part&& part) {
  std::vector<decltype(part(std::size_t{0}, std::size_t{0}))> results(chunk_count(count, chunk));
  for_each_chunk(parallel, count, chunk,
                 [&](std::size_t k, std::size_t begin, std::size_t end) { results[k] = part(begin, end); });
  return results;
}

// Share `share` of `shares` consecutive shares of 0 … count − 1: [first, second).
inline std::pair<std::size_t, std::size_t> share_range(int share, int shares, std::size_t count) {
  const auto n = static_cast<std::size_t>(shares);
  return {count * static_cast<std::size_t>(share) / n, count * static_cast<std::size_t>(share + 1) / n};
}

// body(share, begin, end) over `shares` consecutive shares of 0 … count − 1, side by side (one
// thread each). Only for a body whose every index's result is made whole inside the share that
// holds it, the same way whatever the share (each node's sum over all the elements, in element
// order): then the shares cannot change the answer, and where each share walks all of some
// other list, one share per thread (shares = thread_count()) costs least.
template <class Body>
void for_each_share(int shares, std::size_t count, Body&& body) {
  if (shares <= 1) {
    body(0, std::size_t{0}, count);
    return;
  }
#pragma omp parallel for schedule(static, 1) num_threads(shares)
  for (int s = 0; s < shares; ++s) {
    const auto [begin, end] = share_range(s, shares, count);
    body(s, begin, end);
  }
}

}  // namespace hydrodda::numerics
