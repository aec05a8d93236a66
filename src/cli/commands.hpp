#pragma once
// The subcommands. Each returns the program's exit code (see app.hpp).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/progress.hpp"

namespace hydrodda::sweep {
class SweepRanks;
}

namespace hydrodda::cli {

struct RunOptions {
  std::filesystem::path scenario;               // empty with --resume
  std::optional<std::filesystem::path> resume;  // --resume DIR: continue the coupled run in DIR
  std::optional<std::filesystem::path> output;  // -o: overrides output.directory
  bool overwrite = false;
  std::optional<int> stop_after;  // --stop-after N: a coupled run stops after iteration N, resumable
  std::optional<std::filesystem::path> mesh_cache;  // --mesh-cache DIR: meshes shared with other runs
  std::optional<int> threads;                       // --threads N (run/threads.hpp)
  Verbosity verbosity = Verbosity::Normal;
};

struct SweepOptions {
  std::filesystem::path scenario;
  std::vector<std::string> sets;                // "KEY=V1,V2,..."
  std::optional<std::filesystem::path> output;  // default out/<scenario stem>-sweep
  std::optional<int> jobs;                      // default: the threads
  std::optional<int> threads;                   // --threads N: of all the cases (run/threads.hpp)
  std::vector<std::string> columns;             // dotted paths into summary.json
  bool overwrite = false;
  bool zip = false;                             // the --set lists taken together, not combined
  std::optional<std::string> title;             // sweep.png's title (default: the scenario's)
};

struct BreachOptions {
  std::filesystem::path scenario;
  std::vector<std::string> keys;                // --vary KEY (repeatable: moved together)
  double from = 0.0, to = 0.0;                  // --from, --to
  int steps = 10;                               // --steps
  double tolerance = 5e-3;                      // --tolerance: the bracket's width, a share of the load
  std::optional<std::string> limit;             // --limit PATH=VALUE
  bool converged_only = false;                  // --converged-only: an unsettled step breaks
  std::optional<std::filesystem::path> output;  // default out/<scenario stem>-breach
  std::optional<int> threads;
  bool overwrite = false;
};

// Validates `scenario`; with `figure`, also draws its preview there (run/preview.hpp).
int check_command(const std::filesystem::path& scenario, const std::optional<std::filesystem::path>& figure = std::nullopt);
int run_command(const RunOptions& options);
// `hydrodda sweep`: on this process, or under mpirun over its ranks (rank 0 runs sweep_command,
// the others serve it, sweep/ranks.hpp); the exit code.
int sweep_on_ranks(const SweepOptions& options);
// Under mpirun, rank 0's sweep (the other ranks serve it, sweep/ranks.hpp).
int sweep_command(const SweepOptions& options, sweep::SweepRanks& ranks);
int breach_command(const BreachOptions& options);

}  // namespace hydrodda::cli
