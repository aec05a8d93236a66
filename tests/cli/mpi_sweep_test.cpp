// `mpirun -n 2 hydrodda sweep` through the real program: the cases spread over both ranks and
// sweep.csv the same, byte for byte, as the plain sweep's. Skipped, saying why, where mpirun is
// not installed; where the program was built without MPI, the launch must be refused.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::fresh_dir;
using hydrodda::testing::read_file;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

const fs::path kSource = HYDRODDA_SOURCE_DIR;

// mpirun with two ranks on this machine, whatever its core count; CI runs as root, which Open
// MPI refuses unless told. Under `make asan` the ranks run without LeakSanitizer (-x sets their
// environment; AddressSanitizer's other checks stay on): Open MPI frees none of its start-up
// allocations and unloads the components that made them, so its leaks cannot be named in a
// suppression; every other test of the program checks for leaks. Without the sanitizers the
// variable is read by nothing.
std::string mpirun_two_ranks() {
  std::string command = "mpirun -n 2 --oversubscribe -x ASAN_OPTIONS=detect_leaks=0";
  if (::geteuid() == 0) command += " --allow-run-as-root";
  return command + " " + HYDRODDA_BINARY + " ";
}

bool built_with_mpi() { return run_program("--version").output.find("with MPI") != std::string::npos; }

// Two sweeps of the same cases, one under mpirun -n 2: the same sweep.csv.
void expect_same_sweep(const std::string& arguments, const std::string& name, bool both_ranks_run) {
  const auto plain_folder = fresh_dir("hydrodda-mpi-plain-" + name);
  const auto ranks_folder = fresh_dir("hydrodda-mpi-ranks-" + name);
  const fs::path& plain = plain_folder.path;
  const fs::path& ranks = ranks_folder.path;
  const auto local = run_program("sweep " + arguments + " --jobs 2 -o " + plain.string());
  const auto mpi = run_command(mpirun_two_ranks() + "sweep " + arguments + " -o " + ranks.string());
  EXPECT_EQ(mpi.exit_code, local.exit_code) << mpi.output << "\n---\n" << local.output;
  // Each rank ran cases: rank 0 its own and rank 1 those it was handed (with four cases rank 1
  // asks for one long before rank 0's first, a whole program start, has ended).
  if (both_ranks_run) {
    EXPECT_NE(mpi.output.find(", rank 0]"), std::string::npos) << mpi.output;
    EXPECT_NE(mpi.output.find(", rank 1]"), std::string::npos) << mpi.output;
  }
  const std::string csv = read_file(plain / "sweep.csv");
  EXPECT_FALSE(csv.empty());
  EXPECT_EQ(read_file(ranks / "sweep.csv"), csv);
  EXPECT_EQ(fs::exists(ranks / "sweep.png"), fs::exists(plain / "sweep.png"));
}

bool skip_without_mpirun() {
  return run_command("command -v mpirun").exit_code != 0;
}

}  // namespace

TEST(MpiSweep, SpreadsTheCasesOverTheRanksAndWritesTheSameSweepCsv) {
  if (skip_without_mpirun()) GTEST_SKIP() << "mpirun not found: install openmpi-bin (scripts/install-deps.sh)";
  if (!built_with_mpi()) GTEST_SKIP() << "hydrodda was built without MPI (no libopenmpi-dev when CMake ran)";
  // Flow only, four cases: K_eff and the heads through both ranks.
  expect_same_sweep((kSource / "scenarios/verification/flow_linear_head.toml").string() +
                        " --set flow.boundary[0].head=3,5 --set flow.region[0].permeability=1e-12,2e-12",
                    "flow", true);
  // Mechanics, one case failing: its status and message cross from the rank that ran it.
  expect_same_sweep((kSource / "scenarios/verification/free_fall.toml").string() +
                        " --set mechanics.end_time=0.05 --set material.rock.density=2500,1e308"
                        " --column measure.centre.displacement.1",
                    "failed", false);
}

TEST(MpiSweep, JobsIsRefusedUnderMpirun) {
  if (skip_without_mpirun()) GTEST_SKIP() << "mpirun not found: install openmpi-bin (scripts/install-deps.sh)";
  const auto folder = fresh_dir("hydrodda-mpi-jobs");
  const fs::path& out = folder.path;
  const auto result = run_command(mpirun_two_ranks() + "sweep " +
                                  (kSource / "scenarios/verification/flow_linear_head.toml").string() +
                                  " --set flow.boundary[0].head=3,5 --jobs 2 -o " + out.string());
  EXPECT_NE(result.exit_code, 0) << result.output;
  // With MPI: --jobs means nothing per rank; without: the ranks would each run the whole sweep.
  EXPECT_NE(result.output.find(built_with_mpi() ? "--jobs does not apply under mpirun" : "built without MPI"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
}
