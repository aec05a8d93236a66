#include "run/threads.hpp"

#include <spdlog/spdlog.h>
#include <stdlib.h>

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

// One thread when other processes already keep every core busy (the last minute's load
// average at least the cores) and nobody chose a count. At each barrier OpenMP's waiting thread
// spins before it sleeps, and on a full machine it spins on the core the thread it waits for
// needs: the 1,601-block wall's 20 steps took 3.9 s of CPU and 25–30 s on two threads under a
// load of 13, 0.35 s and 3–5 s on one.
int use_threads(std::optional<int> requested, bool spare_busy_machine) {
  if (const std::optional<int> n = chosen_thread_count(requested)) {
    numerics::set_thread_count(*n);
    spdlog::debug("{} thread(s), as chosen", *n);
    return *n;
  }
  const int cores = numerics::thread_count();
  double load[1] = {0.0};
  if (spare_busy_machine && !std::getenv("OMP_NUM_THREADS") && cores > 1 && ::getloadavg(load, 1) == 1 &&
      load[0] >= static_cast<double>(cores)) {
    numerics::set_thread_count(1);
    spdlog::debug("one thread: the machine's load ({:.1f}) fills its {} cores", load[0], cores);
    return 1;
  }
  spdlog::debug("{} thread(s): the cores this process may use", cores);
  return cores;
}

ThreadsOfThisCall::ThreadsOfThisCall(std::optional<int> requested)
    : previous_(numerics::set_thread_count_of_this_thread(chosen_thread_count(requested).value_or(0))) {}

ThreadsOfThisCall::~ThreadsOfThisCall() { numerics::set_thread_count_of_this_thread(previous_); }

}  // namespace hydrodda::run
