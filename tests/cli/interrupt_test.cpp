// SIGINT in the middle of a long coupling pass: the program does not wait for the pass to end,
// it exits with 1 and leaves summary.json describing the last finished state.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "run_program.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Waits for `pid` up to `limit`; kills it and returns false when it is still running then.
bool wait_for_exit(pid_t pid, std::chrono::seconds limit, int& status) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return false;
}

}  // namespace

TEST(Interrupt, ALongCouplingPassStopsAtTheNextStepAndReportsTheLastFinishedState) {
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-interrupt-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The six-block model with a first pass of a million DDA steps (many minutes): only an
  // interrupt between steps ends it in time.
  std::string text = read_text(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper/six_block_lr_rl.toml");
  const std::string steps = "steps = 100\n";
  ASSERT_NE(text.find(steps), std::string::npos);
  text.replace(text.find(steps), steps.size(), "steps = 1000000\n");
  const fs::path scenario = dir / "long_pass.toml";
  std::ofstream(scenario) << text;
  const fs::path out = dir / "run";

  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execl(HYDRODDA_BINARY, HYDRODDA_BINARY, "run", scenario.c_str(), "-o", out.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // scenario.toml is written just before the first pass starts.
  for (int i = 0; i < 600 && !fs::exists(out / "scenario.toml"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // well inside the first pass
  ::kill(pid, SIGINT);
  int status = 0;
  ASSERT_TRUE(wait_for_exit(pid, std::chrono::seconds(60), status)) << "the interrupt was not taken mid-pass";
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);

  const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["converged"], false);
  EXPECT_EQ(summary["iterations"], 0);
  const std::string message = summary["message"];
  EXPECT_NE(message.find("interrupted: coupling iteration 1 stopped at DDA step"), std::string::npos) << message;
  // No pass finished, so the blocks reported are the blocks as built: the steps taken before the
  // interrupt (which moved them under gravity and the fluid loads) are not reported as results.
  for (const auto& block : summary["blocks"]) {
    EXPECT_EQ(block["displacement"][0].get<double>(), 0.0) << "block " << block["id"];
    EXPECT_EQ(block["displacement"][1].get<double>(), 0.0) << "block " << block["id"];
  }
  fs::remove_all(dir);
}
