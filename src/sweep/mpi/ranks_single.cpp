// SweepRanks without MPI (CMake found none): one rank, the sweep run as child processes on
// this machine; a launch by mpirun with several ranks is refused, as each would run the whole
// sweep into the same folder.
#include <stdexcept>
#include <string>

#include "sweep/ranks.hpp"

namespace hydrodda::sweep {

SweepRanks::SweepRanks(std::function<bool()> stop_requested) : stop_requested_(std::move(stop_requested)) {
  const int launched = launcher_rank_count();
  if (launched > 1)
    throw std::runtime_error("this hydrodda was built without MPI, so " + std::to_string(launched) +
                             " ranks would each run the whole sweep; install libopenmpi-dev and build again, or run "
                             "the sweep without mpirun (--jobs sets the cases run at a time)");
}

SweepRanks::~SweepRanks() = default;

std::vector<std::size_t> SweepRanks::run_cases(const SweepPlan&, const CaseFinished&) {
  throw std::logic_error("SweepRanks::run_cases: one rank only without MPI");
}

void SweepRanks::finish(int) {}

int SweepRanks::serve() { throw std::logic_error("SweepRanks::serve: one rank only without MPI"); }

std::string SweepRanks::build_description() { return "without MPI"; }

}  // namespace hydrodda::sweep
