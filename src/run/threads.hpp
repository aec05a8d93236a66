#pragma once
// How many threads a run uses: the front end's choice (the command line's --threads, Python's
// threads=), else the HYDRODDA_THREADS variable, else every core the process may use
// (numerics::usable_core_count). The results are the same bit for bit on any number.

#include <optional>
#include <string_view>

namespace hydrodda::run {

inline constexpr const char* kThreadsVariable = "HYDRODDA_THREADS";

// A thread count as --threads, threads= and HYDRODDA_THREADS take it: a whole number from 1 to
// 4096 (digits only); nothing otherwise.
std::optional<int> parse_thread_count(std::string_view text);

// `requested` if given, else HYDRODDA_THREADS's value where it is set, else nothing (the
// machine's count, numerics::thread_count()). Throws InputError naming HYDRODDA_THREADS and its
// value when that is not a whole number ≥ 1.
std::optional<int> chosen_thread_count(std::optional<int> requested);

// Sets the threads of every run of this process (the command line's run and sweep):
// chosen_thread_count(requested), else the machine's count; with nothing chosen and
// `spare_busy_machine`, the cores the load average leaves free (the cores less the load,
// rounded; at least one). Returns
// the count set. Throws as chosen_thread_count does.
int use_threads(std::optional<int> requested, bool spare_busy_machine);
// The cores a load average leaves free: cores − round(load), at least one (and `cores` for a
// load that is not a number).
int cores_left_free(int cores, double load);

// For the calls made on the constructing thread while it lives, chosen_thread_count(requested)
// threads where something was chosen (a Python run's threads=): two runs side by side in one
// process each keep their own count. Throws as chosen_thread_count does.
class ThreadsOfThisCall {
 public:
  explicit ThreadsOfThisCall(std::optional<int> requested);
  ~ThreadsOfThisCall();
  ThreadsOfThisCall(const ThreadsOfThisCall&) = delete;
  ThreadsOfThisCall& operator=(const ThreadsOfThisCall&) = delete;

 private:
  int previous_;
};

}  // namespace hydrodda::run
