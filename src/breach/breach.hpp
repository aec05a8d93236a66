#pragma once
// `hydrodda breach`: the load at which a coupled model stops holding, found on one model along
// its loading path (load_search.hpp), written into a breach folder: breach.csv (one row per
// step), breach.json (the bracket and the state just before it), steps/step_NNN.json (each
// state that held, as summary.json), the held states as ParaView series over the load, and the
// curves of the regions' K_eff/K_m and the largest opening against the load (docs/breach.md).

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "breach/coupled_stepper.hpp"
#include "breach/load_search.hpp"

namespace hydrodda::breach {

struct BreachJob {
  std::filesystem::path scenario;   // the file, named in messages and the base of relative paths
  std::optional<std::string> text;  // its text when not read from `scenario` (Python's Scenario)
  std::vector<std::string> keys;     // the varied values' key paths, moved together
  SearchSettings search;
  std::optional<Limit> limit;        // a summary.json value that must stay at or below a bound
  std::filesystem::path directory;   // the breach folder
  bool overwrite = false;
};

struct BreachOutcome {
  SearchResult search;
  std::filesystem::path folder;
  std::string verdict;  // one line: where the breach lies, or that none was found
};

// Builds the model at the first load and searches. Throws scenario::ScenarioError for a
// scenario that cannot be read or built, std::invalid_argument for a key or settings that cannot
// be searched, output::RunFolderError for a folder that cannot be written. Once
// `stop_requested()`, the step under way ends and the folder holds what was found.
BreachOutcome run_breach(const BreachJob& job, const std::function<bool()>& stop_requested);

// The verdict line of a search over `keys` (named by the first, its unit from it: m, Pa, m/s):
// which rule's breach (mechanical, or converged only), the bracket, and how many steps below it
// held unsettled with the worst spread.
std::string describe_verdict(const SearchResult& result, const std::vector<std::string>& keys,
                             const SearchSettings& settings, const std::optional<UnsettledSpread>& worst = std::nullopt);
// "flow.boundary[0].head" or "flow.boundary[0].head (and 1 more)".
std::string name_keys(const std::vector<std::string>& keys);

}  // namespace hydrodda::breach
