#include "numerics/parallel.hpp"

#include <sched.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hydrodda::numerics {

namespace {

std::atomic<int> chosen_threads{0};  // 0: not set
thread_local int threads_of_this_thread = 0;  // 0: the process's

std::string first_line(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// The cgroup v2 folder of this process ("0::/path" in /proc/self/cgroup), or nothing.
std::string own_cgroup_v2() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("0::", 0) == 0) return line.substr(3);
  return {};
}

// The smallest quota on the way from this process's cgroup up to the root (a quota binds the
// groups under it), or 0 for none.
int cores_of_quota() {
  int least = 0;
  const auto take = [&](int cores) {
    if (cores > 0 && (least == 0 || cores < least)) least = cores;
  };
  std::string group = own_cgroup_v2();
  if (!group.empty() && group.find("..") == std::string::npos) {
    while (true) {
      take(cores_of_cpu_max(first_line("/sys/fs/cgroup" + (group == "/" ? std::string() : group) + "/cpu.max")));
      if (group == "/" || group.empty()) break;
      group = group.substr(0, group.find_last_of('/'));
      if (group.empty()) group = "/";
    }
  }
  // cgroup v1, as a container sees it mounted.
  const std::string quota = first_line("/sys/fs/cgroup/cpu/cpu.cfs_quota_us");
  const std::string period = first_line("/sys/fs/cgroup/cpu/cpu.cfs_period_us");
  if (!quota.empty() && !period.empty()) take(cores_of_cpu_max(quota + " " + period));
  return least;
}

// OpenMP's count (OMP_NUM_THREADS, omp_set_num_threads, else the CPUs of the affinity mask, as
// libgomp counts them), no more than the CPU quota unless OMP_NUM_THREADS asks for more.
int default_thread_count() {
  static const bool openmp_variable = std::getenv("OMP_NUM_THREADS") != nullptr;
  static const int quota = cores_of_quota();
  const int openmp = std::max(1, omp_get_max_threads());
  return quota > 0 && !openmp_variable ? std::min(openmp, quota) : openmp;
}

}  // namespace

int cores_of_cpu_max(const std::string& line) {
  std::istringstream in(line);
  std::string quota_text;
  long long period = 0;
  if (!(in >> quota_text >> period) || period <= 0 || quota_text == "max") return 0;
  char* end = nullptr;
  errno = 0;
  const long long quota = std::strtoll(quota_text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || quota <= 0) return 0;  // cgroup v1's −1: no quota
  return static_cast<int>(std::max(1LL, (quota + period - 1) / period));
}

int usable_core_count() {
  int cores = 0;
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof set, &set) == 0) cores = CPU_COUNT(&set);
  if (cores < 1) cores = std::max(1, omp_get_num_procs());
  const int quota = cores_of_quota();
  if (quota > 0) cores = std::min(cores, quota);
  return std::max(1, cores);
}

int thread_count() {
  if (threads_of_this_thread > 0) return threads_of_this_thread;
  const int chosen = chosen_threads.load(std::memory_order_relaxed);
  if (chosen > 0) return chosen;
  return default_thread_count();
}

void set_thread_count(int n) {
  if (n < 1) throw std::invalid_argument("the thread count must be at least 1");
  chosen_threads.store(n, std::memory_order_relaxed);
}

int set_thread_count_of_this_thread(int n) {
  if (n < 0) throw std::invalid_argument("the thread count must be at least 1");
  const int previous = threads_of_this_thread;
  threads_of_this_thread = n;
  return previous;
}

void start_threads() {
  const int threads = thread_count();
  if (threads < 2) return;
#pragma omp parallel num_threads(threads)
  {
  }
}

}  // namespace hydrodda::numerics
