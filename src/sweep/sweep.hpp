#pragma once
// `hydrodda sweep`'s run once its cases are prepared: the sweep's folder and each case's, every
// case a child `hydrodda run` of this same program in its own folder, several at a time (or one
// per MPI rank under mpirun, sweep/ranks.hpp), their results gathered into sweep.csv as they end
// and plotted in sweep.png.

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sweep/cases.hpp"
#include "sweep/preparation.hpp"
#include "sweep/ranks.hpp"

namespace hydrodda::sweep {

struct SweepJob {
  std::filesystem::path scenario;   // the base scenario file
  std::filesystem::path directory;  // the sweep's folder
  std::vector<SweepAxis> axes;
  std::vector<std::vector<scenario::Override>> cases;  // the values of each case
  bool zip = false;                                    // the axes taken together, not combined
  std::vector<std::string> columns;                    // summary.json paths sweep.csv holds
  std::vector<std::string> boundary_names;             // of the base scenario, naming the swept values
  int jobs = 1;                                        // cases at a time on one rank
  int case_threads = 1;                                // each case's --threads
  bool overwrite = false;                              // replace the results in `directory`
  std::string title;                                   // sweep.png's
};

struct SweepOutcome {
  std::size_t cases = 0;
  std::size_t not_ok = 0;   // cases without a converged result
  std::string describe_not_ok;  // "2 failed, 1 not converged"
  std::filesystem::path table;  // sweep.csv
};

// The sweep stopped while its cases ran: they could not be started or sweep.csv written.
class SweepFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes the sweep's folder and the prepared cases' scenario files, runs them over `ranks` (with
// `job.jobs` at a time when there is one), and writes sweep.csv and sweep.png. Once
// `stop_requested()`, no further case starts. Throws output::RunFolderError when the folder
// cannot be made (nothing has run), SweepFailed when the cases cannot be run (sweep.csv then
// holds what ended, if it can be written).
SweepOutcome run_sweep(const SweepJob& job, const std::vector<PreparedCase>& prepared, SweepRanks& ranks,
                       const std::function<bool()>& stop_requested);

}  // namespace hydrodda::sweep
