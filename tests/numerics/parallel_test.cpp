// The process's threads (numerics/parallel.hpp): how many, and loops whose answer does not
// depend on that.

#include "numerics/parallel.hpp"

#include <gtest/gtest.h>
#include <sched.h>

#include <atomic>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

namespace hydrodda::numerics {
namespace {

// Sets the count of this thread for one test, and takes it back.
class ThreadsForTest {
 public:
  explicit ThreadsForTest(int n) : previous_(set_thread_count_of_this_thread(n)) {}
  ~ThreadsForTest() { set_thread_count_of_this_thread(previous_); }

 private:
  int previous_;
};

TEST(Parallel, CpuMaxLinesGiveTheCoresTheirQuotaAllows) {
  EXPECT_EQ(cores_of_cpu_max("max 100000"), 0);
  EXPECT_EQ(cores_of_cpu_max("200000 100000"), 2);
  EXPECT_EQ(cores_of_cpu_max("150000 100000"), 2);  // 1.5 cores: two threads share them
  EXPECT_EQ(cores_of_cpu_max("50000 100000"), 1);
  EXPECT_EQ(cores_of_cpu_max("-1 100000"), 0);  // cgroup v1's "no quota"
  EXPECT_EQ(cores_of_cpu_max(""), 0);
  EXPECT_EQ(cores_of_cpu_max("lots 100000"), 0);
  EXPECT_EQ(cores_of_cpu_max("100000 0"), 0);
}

TEST(Parallel, UsableCoresAreThoseOfTheAffinityMaskAtMost) {
  cpu_set_t set;
  CPU_ZERO(&set);
  ASSERT_EQ(::sched_getaffinity(0, sizeof set, &set), 0);
  const int cores = usable_core_count();
  EXPECT_GE(cores, 1);
  EXPECT_LE(cores, CPU_COUNT(&set));
}

TEST(Parallel, ThisThreadsCountComesBeforeTheProcesssAndIsItsOwn) {
  const ThreadsForTest three(3);
  EXPECT_EQ(thread_count(), 3);
  int other = 0;
  std::thread([&] {
    const ThreadsForTest five(5);
    other = thread_count();
  }).join();
  EXPECT_EQ(other, 5);
  EXPECT_EQ(thread_count(), 3);
  EXPECT_THROW(set_thread_count(0), std::invalid_argument);
  EXPECT_THROW(set_thread_count_of_this_thread(-1), std::invalid_argument);
}

// Each index once, each chunk of the given size, the chunks' results in chunk order, on 1, 2,
// 3 and 8 threads alike.
TEST(Parallel, ChunksAreTheSameOnAnyNumberOfThreads) {
  const std::size_t count = 10007, chunk = 100;
  std::vector<std::vector<std::size_t>> sums;
  for (int threads : {1, 2, 3, 8}) {
    const ThreadsForTest set(threads);
    std::vector<std::atomic<int>> visits(count);
    for_each_index(true, count, [&](std::size_t i) { visits[i]++; });
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(visits[i].load(), 1) << i << " on " << threads;
    const auto results = results_in_chunks(true, count, chunk, [&](std::size_t begin, std::size_t end) {
      EXPECT_EQ(begin % chunk, 0u);
      EXPECT_TRUE(end - begin == chunk || end == count);
      std::size_t sum = 0;
      for (std::size_t i = begin; i < end; ++i) sum += i;
      return sum;
    });
    ASSERT_EQ(results.size(), chunk_count(count, chunk));
    EXPECT_EQ(std::accumulate(results.begin(), results.end(), std::size_t{0}), count * (count - 1) / 2);
    sums.push_back(results);
  }
  for (const auto& s : sums) EXPECT_EQ(s, sums[0]);
  EXPECT_EQ(chunk_count(0, 100), 0u);
  EXPECT_TRUE(results_in_chunks(true, 0, 100, [](std::size_t, std::size_t) { return 1; }).empty());
}

// Shares cover 0 … count − 1 in order, without gaps or overlaps, however many.
TEST(Parallel, SharesCoverTheRangeOnce) {
  for (int shares : {1, 2, 3, 8}) {
    std::vector<int> owner(1001, -1);
    for_each_share(shares, owner.size(), [&](int share, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) owner[i] = share;
    });
    for (std::size_t i = 1; i < owner.size(); ++i) EXPECT_LE(owner[i - 1], owner[i]);
    EXPECT_EQ(owner.front(), 0);
    EXPECT_EQ(owner.back(), shares - 1);
  }
}

// Two fixed parts whatever the threads: halves of the same indices on one thread or eight.
TEST(Parallel, TwoPartsAreHalvesOnAnyNumberOfThreads) {
  for (int threads : {1, 8}) {
    const ThreadsForTest set(threads);
    std::vector<std::pair<std::size_t, std::size_t>> parts(2);
    run_two_parts(true, [&](int part) { parts[part] = half_range(part, 11); });
    EXPECT_EQ(parts[0], std::make_pair(std::size_t{0}, std::size_t{5}));
    EXPECT_EQ(parts[1], std::make_pair(std::size_t{5}, std::size_t{11}));
  }
}

}  // namespace
}  // namespace hydrodda::numerics
