#include <cstdio>
#include <exception>

#include "cli/app.hpp"

// Every failure is meant to be caught where it has a clear message; this is the last line of
// defence, so that even a missed one ends with a message and exit code 1, never an abort.
int main(int argc, char** argv) {
  try {
    return hydrodda::cli::run_app(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "error: unexpected failure\n");
  }
  return hydrodda::cli::kRunFailed;
}
