#pragma once
// Progress of a run: a live line rewritten in place on a terminal, plain log lines elsewhere.

#include <chrono>
#include <string>

namespace hydrodda::cli {

enum class Verbosity { Quiet, Normal, Verbose };

class Progress {
 public:
  Progress(Verbosity verbosity, bool terminal);
  ~Progress();

  // One update (iteration or step, residual): shown at once on a terminal, and as a log line
  // at most once a second otherwise, so that a log file stays readable.
  void update(const std::string& text);
  // Ends the live line so that later output starts on a fresh line.
  void finish();
  double elapsed_seconds() const;

 private:
  Verbosity verbosity_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_log_;
};

// Ends the live line, if one is open on stderr: the logger calls it before every message, so
// that no log line continues a progress line.
void end_live_line();

}  // namespace hydrodda::cli
