#pragma once
// Work in two independent parts, side by side on two threads where the OpenMP runtime grants
// them, else one after the other (OMP_NUM_THREADS=1 keeps one thread, as each case of a
// sweep does). The callers split their work into the same two parts either way, so the
// answer does not depend on the number of threads, only on the split.

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include <omp.h>

namespace hydrodda::geometry {

// Runs task(0) and task(1); on two threads if `parallel` (the caller's judgement that the
// parts are large enough to pay for waking a second thread) and two are available.
template <class Task>
void run_two_parts(bool parallel, Task&& task) {
  const int threads = parallel ? std::min(2, omp_get_max_threads()) : 1;
  if (threads == 1) {  // not even a one-thread region: a small model's step has hundreds
    task(0);
    task(1);
    return;
  }
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int part = 0; part < 2; ++part) task(part);
}

// Whether run_two_parts(true, …) would use two threads.
inline bool two_threads_available() { return omp_get_max_threads() >= 2; }

// Has the OpenMP runtime make its second thread now, with the model, rather than inside the
// first step: a process's first parallel region takes from half a millisecond to ten on a
// virtual machine, the time to create the thread and to have the host run it.
inline void start_second_thread() {
  run_two_parts(true, [](int) {});
}

// Part `part` (0 or 1) of 0 … count − 1 split in halves: [first, second).
inline std::pair<std::size_t, std::size_t> half_range(int part, std::size_t count) {
  const std::size_t half = count / 2;
  if (part == 0) return {0, half};
  return {half, count};
}

// body(i) for every i in 0 … count − 1, the two halves side by side where `parallel`. Each i
// is visited once, by the same code either way: a body that writes only its own i's data
// gives the same answer on one thread or two.
template <class Body>
void for_each_in_halves(bool parallel, std::size_t count, Body&& body) {
  run_two_parts(parallel, [&](int part) {
    const auto [begin, end] = half_range(part, count);
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

// part(begin, end) over each half [begin, end) of 0 … count − 1, side by side where
// `parallel`: the two halves' results, the first half's first, for the caller to combine.
template <class Part>
auto results_in_halves(bool parallel, std::size_t count, Part&& part) {
  std::array<decltype(part(std::size_t{0}, std::size_t{0})), 2> results{};
  run_two_parts(parallel, [&](int p) {
    const auto [begin, end] = half_range(p, count);
    results[p] = part(begin, end);
  });
  return results;
}

}  // namespace hydrodda::geometry
