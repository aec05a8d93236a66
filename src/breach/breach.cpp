#include "breach/breach.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "breach/breach_files.hpp"
#include "output/run_folder.hpp"

namespace hydrodda::breach {

namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("{}: cannot be read", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string unit_of(const std::string& key) {
  if (key.ends_with(".head")) return "m";
  if (key.ends_with(".flux")) return "m/s";
  return "Pa";
}

}  // namespace

std::string name_keys(const std::vector<std::string>& keys) {
  if (keys.empty()) return "";
  return keys.size() == 1 ? keys[0] : fmt::format("{} (and {} more)", keys[0], keys.size() - 1);
}

std::string describe_unsettled(int steps, const std::optional<UnsettledSpread>& worst) {
  if (steps == 0 || !worst) return "";
  return fmt::format("; {} step{} below it held unsettled (blocks at rest, the loop not converged), K_eff/K_m of '{}' "
                     "swinging by up to {:.2g}% over the last passes (at {:.6g})",
                     steps, steps == 1 ? "" : "s", worst->region, 100.0 * worst->spread, worst->load);
}

std::string describe_verdict(const SearchResult& r, const std::vector<std::string>& keys, const SearchSettings& settings,
                             const std::optional<UnsettledSpread>& worst) {
  const std::string key = name_keys(keys);
  const std::string unit = keys.empty() ? "" : unit_of(keys[0]);
  const std::string unsettled = describe_unsettled(r.unsettled_held, worst);
  if (r.interrupted)
    return r.held ? fmt::format("interrupted; {} held up to {:.6g} {}{}", key, *r.held, unit, unsettled)
                  : fmt::format("interrupted before any load held");
  if (!r.broken)
    return fmt::format("no breach: every step held up to {} = {:.6g} {}{}", key, settings.to, unit, unsettled);
  const std::string how = status_name(*r.broken_status);
  if (!r.held)
    return fmt::format("breach below the first load: {} = {:.6g} {} did not hold ({})", key, *r.broken, unit, how);
  return fmt::format("{} breach between {} = {:.6g} and {:.6g} {} (width {:.2g}% of the load{}): the last held, the "
                     "first {}{}",
                     settings.converged_only ? "converged-only" : "mechanical", key, *r.held, *r.broken, unit,
                     100.0 * std::abs(*r.broken - *r.held) / std::abs(*r.broken),
                     r.narrowed ? "" : fmt::format(", not narrowed to the tolerance {:g}%", 100.0 * settings.tolerance),
                     how, unsettled);
}

BreachOutcome run_breach(const BreachJob& job, const std::function<bool()>& stop_requested) {
  check_settings(job.search);
  const std::string text = job.text ? *job.text : read_text(job.scenario);
  const output::RunFolder folder(job.directory,
                                 job.overwrite ? output::ExistingFolder::Overwrite : output::ExistingFolder::Refuse);
  CoupledStepper stepper(text, job.scenario, job.keys, job.search.from, job.limit, stop_requested);
  BreachFiles files(folder, stepper.scenario(), name_keys(job.keys), job.limit, stepper.model().mechanics());
  files.write_scenario(text);
  const auto on_step = [&](const SearchStep& step) {
    spdlog::info("step {}: {} = {:.6g}: {} in {} pass(es){}", step.index, name_keys(job.keys), step.load,
                 status_name(step.result.status), step.result.passes,
                 step.result.message.empty() ? "" : ": " + step.result.message);
    files.add_step(step, stepper, holds(step.result.status, job.search));
  };
  BreachOutcome outcome{search_breach(job.search, stepper, on_step), folder.path(), ""};
  outcome.verdict = describe_verdict(outcome.search, job.keys, job.search, files.worst_unsettled_spread());
  if (outcome.search.held) {
    stepper.back_to_kept_state();
    files.write_last_held(*outcome.search.held, stepper);
  }
  files.finish(outcome.search, outcome.verdict, job.search);
  return outcome;
}

}  // namespace hydrodda::breach
