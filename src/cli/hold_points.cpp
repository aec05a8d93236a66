#include "cli/hold_points.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/interrupt.hpp"

namespace hydrodda::cli {

namespace {

long long read_count(const char* variable, long long otherwise) {
  const char* value = std::getenv(variable);
  return value ? std::atoll(value) : otherwise;
}

void hold(const std::string& where) {
  std::fputs(fmt::format("held: {}; waiting for an interrupt\n", where).c_str(), stderr);
  std::fflush(stderr);
  wait_for_interrupt();
}

class LineHold : public spdlog::sinks::sink {
 public:
  LineHold(std::string text, long long count) : text_(std::move(text)), count_(count) {}
  void log(const spdlog::details::log_msg& msg) override {
    const std::string_view line(msg.payload.data(), msg.payload.size());
    if (line.find(text_) == std::string_view::npos || ++seen_ != count_) return;
    hold(fmt::format("after line {} containing \"{}\"", count_, text_));
  }
  void flush() override {}
  void set_pattern(const std::string&) override {}
  void set_formatter(std::unique_ptr<spdlog::formatter>) override {}

 private:
  std::string text_;
  long long count_;
  std::atomic<long long> seen_{0};
};

}  // namespace

std::shared_ptr<spdlog::sinks::sink> make_line_hold_sink() {
  const char* text = std::getenv("HYDRODDA_HOLD_AFTER_LINE");
  if (!text) return nullptr;
  auto sink = std::make_shared<LineHold>(text, read_count("HYDRODDA_HOLD_COUNT", 1));
  sink->set_level(spdlog::level::trace);
  return sink;
}

void pass_stop_check() {
  static const long long chosen = read_count("HYDRODDA_HOLD_AT_STOP_CHECK", 0);
  static std::atomic<long long> checks{0};
  if (chosen > 0 && ++checks == chosen) hold(fmt::format("at stop check {}", chosen));
}

}  // namespace hydrodda::cli
