// Every file in tests/cli/bad_scenarios is a scenario with one mistake. Its first two lines say
// what `hydrodda check` must print: "# expect: <fragment>" and "# line: <N>" (the line the
// error must name, 0 for none). The check must exit with code 2 and print exactly one error.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "run_program.hpp"

namespace fs = std::filesystem;

namespace {

struct BadScenario {
  fs::path file;
  std::string fragment;
  int line = 0;
};

// Names the case by its file in test logs rather than dumping its bytes.
void PrintTo(const BadScenario& bad, std::ostream* os) { *os << bad.file.filename().string(); }

std::vector<BadScenario> load_corpus() {
  std::vector<BadScenario> corpus;
  for (const auto& entry : fs::directory_iterator(fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/bad_scenarios")) {
    if (entry.path().extension() != ".toml") continue;
    std::ifstream in(entry.path());
    std::string expect_line, line_line;
    std::getline(in, expect_line);
    std::getline(in, line_line);
    BadScenario bad{entry.path(), expect_line.substr(std::string("# expect: ").size()),
                    std::stoi(line_line.substr(std::string("# line: ").size()))};
    corpus.push_back(std::move(bad));
  }
  std::sort(corpus.begin(), corpus.end(), [](const auto& a, const auto& b) { return a.file < b.file; });
  return corpus;
}

class BadScenarioTest : public ::testing::TestWithParam<BadScenario> {};

TEST_P(BadScenarioTest, CheckNamesFileLineAndKey) {
  const BadScenario& bad = GetParam();
  const auto result = hydrodda::testing::run_program("check " + bad.file.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find(bad.fragment), std::string::npos)
      << "expected \"" << bad.fragment << "\" in:\n" << result.output;
  if (bad.line > 0) {
    const std::string location = bad.file.string() + ":" + std::to_string(bad.line) + ": ";
    EXPECT_NE(result.output.find(location), std::string::npos)
        << "expected \"" << location << "\" in:\n" << result.output;
  }
  EXPECT_NE(result.output.find("1 error(s)"), std::string::npos) << result.output;
}

TEST_P(BadScenarioTest, RunRefusesBeforeWritingAnything) {
  const BadScenario& bad = GetParam();
  const fs::path out = fs::temp_directory_path() / ("hydrodda-bad-" + bad.file.stem().string());
  fs::remove_all(out);
  const auto result = hydrodda::testing::run_program("run " + bad.file.string() + " -o " + out.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_FALSE(fs::exists(out)) << "a bad scenario must not create its run folder";
}

TEST(BadScenarioCorpus, HoldsAtLeastForty) { EXPECT_GE(load_corpus().size(), 40u); }

INSTANTIATE_TEST_SUITE_P(Corpus, BadScenarioTest, ::testing::ValuesIn(load_corpus()),
                         [](const auto& info) { return info.param.file.stem().string(); });

}  // namespace
