#pragma once
// The command-line program: parses arguments, runs a subcommand, maps failures to exit codes.

namespace hydrodda::cli {

// Exit codes of the program.
enum ExitCode : int { kSuccess = 0, kRunFailed = 1, kBadInput = 2 };

int run_app(int argc, char** argv);

}  // namespace hydrodda::cli
