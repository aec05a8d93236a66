// `hydrodda sweep`: a scenario run once per combination of swept values, each case a child
// `hydrodda run` of this same program in its own folder, several at a time (or one per MPI
// rank under mpirun, cli/sweep_ranks.hpp); their results gathered into sweep.csv and plotted
// in sweep.png.

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "cli/app.hpp"
#include "cli/child_processes.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/scenario_loading.hpp"
#include "cli/sweep_ranks.hpp"
#include "output/run_folder.hpp"
#include "run/run.hpp"
#include "run/sweep_plan.hpp"
#include "run/sweep_results.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::cli {

namespace fs = std::filesystem;

namespace {

// The lines of a case's run.log that are warnings ("warning: ..."); 0 without the file.
int count_warnings(const fs::path& log) {
  std::ifstream in(log);
  int count = 0;
  for (std::string line; std::getline(in, line);) count += line.rfind("warning: ", 0) == 0;
  return count;
}

// The cases' shared meshes (run --mesh-cache): cases of one geometry and mesh settings mesh once.
constexpr const char* kMeshCache = "mesh-cache";

struct PreparedCase {
  std::string name;  // case_000
  std::string text;  // the case's scenario file
};

void print_error(const std::string& message) { std::fputs(fmt::format("error: {}\n", message).c_str(), stderr); }

std::string describe_case(const std::vector<scenario::Override>& overrides) {
  std::string text;
  for (const scenario::Override& o : overrides) text += fmt::format("{}{}={}", text.empty() ? "" : ", ", o.key, o.value);
  return text;
}

// A TOML basic string holding `text`.
std::string toml_string(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

// "Six-block model — head at base = 5 m, density = 2000 kg/m³".
std::string case_title(const std::string& base_title, const std::vector<scenario::Override>& values,
                       const std::vector<std::string>& boundary_names) {
  std::string text;
  for (const scenario::Override& o : values)
    text += fmt::format("{}{}", text.empty() ? "" : ", ", run::value_label(o, boundary_names));
  return base_title.empty() ? text : base_title + " — " + text;
}

std::vector<std::string> boundary_names_of(const scenario::Scenario& s) {
  std::vector<std::string> names;
  if (s.flow)
    for (const scenario::FlowBoundaryCondition& b : s.flow->boundaries) names.push_back(b.name);
  return names;
}

// What preparing the cases gave: every case's scenario file, or why not.
struct Preparation {
  std::vector<PreparedCase> cases;
  bool bad_input = false;    // some case failed its check (each problem printed)
  bool interrupted = false;  // an interrupt came first: `cases` holds those checked by then
};

// Every case's scenario file, each read and checked as `run` would, all of them even after one
// fails; an interrupt stops it between cases.
Preparation prepare_cases(const fs::path& file, const fs::path& directory,
                          const std::vector<std::vector<scenario::Override>>& cases, const scenario::Scenario& base,
                          std::vector<std::string>& region_names) {
  const std::string& base_title = base.title;
  const std::vector<std::string> boundary_names = boundary_names_of(base);
  const std::string original = run::read_text_file(file).value_or("");
  Preparation prepared;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (interrupt_requested()) {
      prepared.interrupted = true;
      break;
    }
    const std::string name = fmt::format("case_{:03}", i);
    const fs::path case_file = directory / name / "scenario.toml";
    std::string text;
    try {
      // The case's title names its values, so that its figures say which case they show.
      std::vector<scenario::Override> overrides = cases[i];
      overrides.push_back({"title", toml_string(case_title(base_title, cases[i], boundary_names))});
      text = scenario::apply_overrides(original, file, overrides);
      const scenario::Scenario s = scenario::parse_scenario(text, case_file);
      run::check_model(s);  // as `check` does
      if (i == 0 && s.flow)
        for (const scenario::FlowRegion& r : s.flow->regions) region_names.push_back(r.name);
      prepared.cases.push_back({name, std::move(text)});
      spdlog::debug("{} ({}): checked", name, describe_case(cases[i]));
    } catch (const scenario::ScenarioError& e) {
      print_error(fmt::format("{} ({}):", name, describe_case(cases[i])));
      // Cited in the scenario file and the --set the user wrote: the case's file is not kept.
      for (const scenario::Diagnostic& d : scenario::locate_in_original(e.diagnostics(), text, case_file, original, file, cases[i]))
        print_error(d.format());
      prepared.bad_input = true;
    }
  }
  return prepared;
}

}  // namespace

int sweep_command(const SweepOptions& options, SweepRanks& ranks) {
  const auto base = load_scenario(options.scenario);
  if (!base) return kBadInput;
  std::vector<run::SweepAxis> axes;
  std::vector<std::vector<scenario::Override>> cases;
  try {
    for (const std::string& set : options.sets) axes.push_back(run::parse_sweep_axis(set));
    cases = options.zip ? run::zip_cases(axes) : run::enumerate_cases(axes);
  } catch (const std::invalid_argument& e) {
    print_error(e.what());
    return kBadInput;
  }
  const fs::path directory =
      options.output.value_or(fs::path("out") / (options.scenario.stem().string() + "-sweep"));
  std::vector<std::string> region_names;
  const Preparation preparation = prepare_cases(options.scenario, directory, cases, *base, region_names);
  if (preparation.interrupted) {
    print_error(fmt::format("interrupted while checking the cases ({} of {} checked); nothing was run or written",
                            preparation.cases.size(), cases.size()));
    return kRunFailed;
  }
  if (preparation.bad_input) {
    std::fputs(fmt::format("{}: the sweep was not started\n", options.scenario.string()).c_str(), stderr);
    return kBadInput;
  }
  const std::vector<PreparedCase>& prepared = preparation.cases;
  std::vector<std::string> columns = options.columns;
  if (columns.empty())
    for (const std::string& region : region_names)
      columns.push_back(fmt::format("flow.regions.{}.effective_conductivity", region));

  std::optional<output::RunFolder> folder;
  try {
    folder.emplace(directory, options.overwrite ? output::ExistingFolder::Overwrite : output::ExistingFolder::Refuse);
    // Meshes live as long as the sweep: none made by an earlier sweep (an older program) is read.
    run::clear_mesh_cache(directory / kMeshCache);
    for (const PreparedCase& c : prepared) {
      if (interrupt_requested()) break;  // no case will start: each is listed as not run
      const output::RunFolder case_folder(folder->subfolder(c.name), output::ExistingFolder::Overwrite);
      case_folder.write("scenario.toml", c.text);
      fs::remove(case_folder.file("summary.json"));  // an earlier sweep's result must not be read as this one's
    }
  } catch (const output::RunFolderError& e) {
    print_error(e.what());
    return kBadInput;
  }

  const fs::path program = fs::read_symlink("/proc/self/exe");
  std::vector<ChildCommand> commands;
  for (const PreparedCase& c : prepared) {
    const fs::path case_dir = directory / c.name;
    commands.push_back({{program.string(), "-q", "run", (case_dir / "scenario.toml").string(), "-o",
                         case_dir.string(), "--overwrite", "--mesh-cache", (directory / kMeshCache).string()},
                        case_dir / "run.log"});
  }
  const int jobs = ranks.size() > 1 ? ranks.size() : options.jobs.value_or(std::max(1u, std::thread::hardware_concurrency()));
  spdlog::info("sweep of {}: {} case(s), {} at a time{}, in {}", options.scenario.string(), cases.size(), jobs,
               ranks.size() > 1 ? " (one per MPI rank)" : "", directory.string());

  run::SweepResults results(axes, cases, columns, options.zip);
  for (std::size_t i = 0; i < prepared.size(); ++i) results.set_name(i, prepared[i].name);
  results.set_boundary_names(boundary_names_of(*base));
  std::size_t finished = 0;
  std::vector<std::size_t> never_started;
  try {
    const auto case_finished = [&](std::size_t index, const run::CaseResult& r, int rank) {
      results.set_result(index, r);
      ++finished;
      // A case's warnings (a mesh that does not resolve what it must, blocks off the mesh)
      // qualify its numbers: say that its run.log has some.
      const int warnings = count_warnings(directory / prepared[index].name / "run.log");
      const std::string line = fmt::format(
          "{} ({}): {}{}{}  [{}/{}{}]", prepared[index].name, describe_case(cases[index]),
          run::status_name(r.status), r.message.empty() ? "" : ": " + r.message,
          warnings > 0 ? fmt::format(" ({} warning(s) in {}/run.log)", warnings, prepared[index].name) : "",
          finished, cases.size(), ranks.size() > 1 ? fmt::format(", rank {}", rank) : "");
      if (r.status == run::CaseStatus::ok) spdlog::info("{}", line);
      else if (r.status == run::CaseStatus::failed) spdlog::error("{}", line);
      else spdlog::warn("{}", line);
      folder->write("sweep.csv", results.csv_text());
    };
    SweepPlan plan{commands, {}, columns};
    for (const PreparedCase& c : prepared) plan.folders.push_back(directory / c.name);
    if (ranks.size() > 1) {
      never_started = ranks.run_cases(plan, case_finished);
    } else {
      never_started = run_child_processes(commands, jobs, [&](std::size_t index, int exit_code) {
        case_finished(index,
                      run::read_case_result(prepared[index].name, plan.folders[index], exit_code, columns,
                                            interrupt_requested()),
                      0);
      });
    }
  } catch (const std::exception& e) {
    print_error(e.what());
    folder->write("sweep.csv", results.csv_text());
    return kRunFailed;
  }
  for (std::size_t index : never_started) results.record_not_run(index);
  folder->write("sweep.csv", results.csv_text());
  results.plot(directory / "sweep.png", options.title.value_or(base->title));

  // A case that did not converge counts as failed here: its numbers are not a result, and a
  // script that checks the exit code must not take them for one.
  const std::size_t not_ok = results.count_not_ok();
  if (not_ok > 0) {
    spdlog::error("{} of {} case(s) gave no converged result ({}); see {}", not_ok, cases.size(),
                  results.describe_not_ok(), (directory / "sweep.csv").string());
    return kRunFailed;
  }
  spdlog::info("all {} case(s) converged; results in {}", cases.size(), (directory / "sweep.csv").string());
  return kSuccess;
}

}  // namespace hydrodda::cli
