#include "run/threads.hpp"

#include <spdlog/spdlog.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "numerics/parallel.hpp"
#include "run/run.hpp"

namespace hydrodda::run {

namespace {

constexpr int kMostThreads = 4096;

}  // namespace

std::optional<int> parse_thread_count(std::string_view text) {
  if (text.empty() || text.size() > 4) return std::nullopt;
  int n = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    n = 10 * n + (c - '0');
  }
  if (n < 1 || n > kMostThreads) return std::nullopt;
  return n;
}

std::optional<int> chosen_thread_count(std::optional<int> requested) {
  if (requested) return requested;
  const char* variable = std::getenv(kThreadsVariable);
  if (!variable) return std::nullopt;
  const std::optional<int> n = parse_thread_count(variable);
  if (!n)
    throw InputError(std::string(kThreadsVariable) + " must be a whole number from 1 to " +
                     std::to_string(kMostThreads) + ", got '" + variable + "'");
  return n;
}

// When nobody chose a count, the cores other processes leave free: the cores less the last
// minute's load average, rounded (at least one). At each barrier OpenMP's waiting thread spins
// before it sleeps, and where the threads outnumber the free cores it spins on the core the
// thread it waits for needs: the 1,601-block wall's 20 steps took 3.9 s of CPU and 25–30 s on
// two threads under a load of 13, 0.35 s and 3–5 s on one; under a load of 2.6–6.8, 2.5–8.9 s
// of CPU and 5–22 s on two threads, 0.5–0.65 s and 1.1–1.8 s on one (docs/performance.md).
int use_threads(std::optional<int> requested, bool spare_busy_machine) {
  if (const std::optional<int> n = chosen_thread_count(requested)) {
    numerics::set_thread_count(*n);
    spdlog::debug("{} thread(s), as chosen", *n);
    return *n;
  }
  const int cores = numerics::thread_count();
  double load[1] = {0.0};
  if (spare_busy_machine && !std::getenv("OMP_NUM_THREADS") && cores > 1 && ::getloadavg(load, 1) == 1) {
    const int free_cores = cores_left_free(cores, load[0]);
    if (free_cores < cores) {
      numerics::set_thread_count(free_cores);
      spdlog::debug("{} thread(s): the machine's load ({:.1f}) keeps the rest of its {} cores busy", free_cores,
                    load[0], cores);
      return free_cores;
    }
  }
  spdlog::debug("{} thread(s): the cores this process may use", cores);
  return cores;
}

int cores_left_free(int cores, double load) {
  if (!(load >= 0.0)) return cores;
  const double busy = std::round(std::min(load, static_cast<double>(cores)));
  return std::max(1, cores - static_cast<int>(busy));
}

ThreadsOfThisCall::ThreadsOfThisCall(std::optional<int> requested)
    : previous_(numerics::set_thread_count_of_this_thread(chosen_thread_count(requested).value_or(0))) {}

ThreadsOfThisCall::~ThreadsOfThisCall() { numerics::set_thread_count_of_this_thread(previous_); }

}  // namespace hydrodda::run
