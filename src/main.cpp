#include <cstdio>
#include <exception>

#include "cli/app.hpp"
#include "cli/interrupt.hpp"

// Every failure is meant to be caught where it has a clear message; this is the last line of
// defence, so that even a missed one ends with a message and exit code 1, never an abort.
int main(int argc, char** argv) {
  hydrodda::cli::block_interrupt_signals();  // an early SIGINT or SIGTERM must not end us by default
  try {
    return hydrodda::cli::run_app(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "error: unexpected failure\n");
  }
  return hydrodda::cli::kRunFailed;
}
