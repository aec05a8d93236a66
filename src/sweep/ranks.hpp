#pragma once
// The ranks of `mpirun -n N hydrodda sweep`: rank 0 prepares the sweep as a plain sweep does,
// then hands its cases out one at a time to whichever rank is free (itself included), each
// case a child `hydrodda run` as in a plain sweep; the others run what they are given and send
// back its result. Rank 0 alone writes sweep.csv and sweep.png. Every rank ends with the
// sweep's exit code. Built with MPI (Open MPI) when CMake finds it (sweep/mpi/); without it, a
// launch by mpirun with several ranks is refused rather than run N times over.

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sweep/child_processes.hpp"
#include "sweep/results.hpp"

namespace hydrodda::sweep {

// What a sweep's cases are: each one's command and folder, and the summary.json columns read
// from its result.
struct SweepPlan {
  std::vector<ChildCommand> commands;
  std::vector<std::filesystem::path> folders;
  std::vector<std::string> columns;
};

// Called on rank 0 as each case's result arrives, with the rank that ran it.
using CaseFinished = std::function<void(std::size_t index, const CaseResult& result, int rank)>;

class SweepRanks {
 public:
  // Joins the MPI job when an MPI launcher started the program (its variables are in the
  // environment). Throws std::runtime_error when one started it with several ranks and MPI is
  // not built in.
  explicit SweepRanks(std::function<bool()> stop_requested);
  ~SweepRanks();
  SweepRanks(const SweepRanks&) = delete;
  SweepRanks& operator=(const SweepRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  // Rank 0: runs the plan's cases over every rank, one case per rank at a time, calling
  // `finished` for each. Once stop_requested() (or a rank reports one), no case is
  // started; returns when every running case has ended, with the indices never started.
  std::vector<std::size_t> run_cases(const SweepPlan& plan, const CaseFinished& finished);
  // Rank 0, once the sweep is over (also when it never started): the exit code to every rank.
  void finish(int exit_code);
  // The other ranks: runs the cases rank 0 gives until it says the sweep is over; returns the
  // sweep's exit code.
  int serve();

  // "with MPI (Open MPI v4.1.4)" or "without MPI", for --version.
  static std::string build_description();

 private:
  std::function<bool()> stop_requested_;
  int rank_ = 0;
  int size_ = 1;
  bool joined_ = false;
  bool plan_sent_ = false;
  bool cases_done_ = false;
};

// Ranks of the job as the launcher's environment gives them (Open MPI's, else PMI's), or 0
// when no launcher started the program.
inline int launcher_rank_count() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return 0;
}

}  // namespace hydrodda::sweep
