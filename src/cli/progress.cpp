#include "cli/progress.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>

namespace hydrodda::cli {

namespace {
// One stderr, so one live line at most; written and ended on the thread that runs.
bool live_line_open = false;
}  // namespace

void end_live_line() {
  if (live_line_open) {
    std::fputs("\n", stderr);
    live_line_open = false;
  }
}

Progress::Progress(Verbosity verbosity, bool terminal)
    : verbosity_(verbosity),
      terminal_(terminal),
      start_(std::chrono::steady_clock::now()),
      last_log_(start_ - std::chrono::hours(1)) {}

Progress::~Progress() { finish(); }

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(const std::string& text) {
  if (verbosity_ == Verbosity::Quiet) return;
  const std::string line = fmt::format("{} [{:.1f} s]", text, elapsed_seconds());
  if (terminal_) {
    std::fputs(fmt::format("\r\033[K{}", line).c_str(), stderr);
    std::fflush(stderr);
    live_line_open = true;
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (verbosity_ == Verbosity::Verbose || now - last_log_ >= std::chrono::seconds(1)) {
    spdlog::info("{}", line);
    last_log_ = now;
  }
}

void Progress::finish() { end_live_line(); }

}  // namespace hydrodda::cli
