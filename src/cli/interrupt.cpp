#include "cli/interrupt.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <mutex>
#include <thread>

#include "cli/app.hpp"

namespace hydrodda::cli {

namespace {
std::atomic<bool> requested{false};
std::atomic<bool> taken{false};  // and the process goes on
// Held while deciding to end the process, so that a stage is never ended after it said it ended.
std::mutex exit_mutex;
bool exit_on_interrupt = false;
std::filesystem::path empty_folder_to_remove;

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

[[noreturn]] void exit_now() {
  std::error_code ec;
  if (!empty_folder_to_remove.empty()) std::filesystem::remove(empty_folder_to_remove, ec);  // only if empty
  static const char message[] = "\nerror: interrupted before any result was written; nothing was kept\n";
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(kRunFailed);
}

void take_signals() {
  const sigset_t set = interrupt_signals();
  for (;;) {
    int signal = 0;
    if (::sigwait(&set, &signal) != 0) continue;
    requested = true;
    {
      const std::lock_guard lock(exit_mutex);
      if (exit_on_interrupt) exit_now();
    }
    // Only now, the process going on: a thread waiting for the interrupt never runs past an
    // interrupt that ends the process.
    taken = true;
    taken.notify_all();
  }
}
}  // namespace

void block_interrupt_signals() {
  const sigset_t set = interrupt_signals();
  ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

void start_interrupt_thread() {
  block_interrupt_signals();
  std::thread(take_signals).detach();
}

bool interrupt_requested() { return requested; }

void wait_for_interrupt() { taken.wait(false); }

void set_exit_on_interrupt(bool on, const std::filesystem::path& folder) {
  const std::lock_guard lock(exit_mutex);
  exit_on_interrupt = on;
  empty_folder_to_remove = folder;
  if (on && requested) exit_now();
}

}  // namespace hydrodda::cli
