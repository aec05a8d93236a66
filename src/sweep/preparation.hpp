#pragma once
// A sweep's cases made ready before any runs: each case's scenario file (the base file with the
// case's values and a title naming them), read and checked as `run` would.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "scenario/overrides.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::sweep {

struct PreparedCase {
  std::string name;  // case_000
  std::string text;  // the case's scenario file
};

// What preparing the cases gave: every case's scenario file, or why not.
struct Preparation {
  std::vector<PreparedCase> cases;
  // The problems of the cases that failed their check, each a line naming the case, then its
  // problems cited in the scenario file and the --set the user wrote. Empty: all are good.
  std::vector<std::string> errors;
  bool interrupted = false;               // a stop request came first: `cases` holds those checked by then
  std::vector<std::string> region_names;  // the flow regions of the first case
};

// Every case's scenario file (cases[i] the values of case i), each read and checked as `run`
// would, all of them even after one fails; `stop_requested` is asked between cases.
Preparation prepare_cases(const std::filesystem::path& file, const std::filesystem::path& directory,
                          const std::vector<std::vector<scenario::Override>>& cases, const scenario::Scenario& base,
                          const std::function<bool()>& stop_requested);

// "head=5, density=2000": a case's values as the user wrote them.
std::string describe_case(const std::vector<scenario::Override>& overrides);

// The names of the scenario's flow boundaries, which name the values swept on them.
std::vector<std::string> boundary_names_of(const scenario::Scenario& s);

}  // namespace hydrodda::sweep
