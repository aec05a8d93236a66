#include "cli/app.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <spdlog/pattern_formatter.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "cli/commands.hpp"
#include "cli/hold_points.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "sweep/ranks.hpp"
#include "cli/version.hpp"

namespace hydrodda::cli {

namespace {
// "%*": nothing for informational lines, "warning: " or "error: " for the others, so that
// ordinary output reads as plain text and problems stand out.
class SeverityPrefix : public spdlog::custom_flag_formatter {
 public:
  void format(const spdlog::details::log_msg& msg, const std::tm&, spdlog::memory_buf_t& dest) override {
    std::string_view prefix;
    if (msg.level == spdlog::level::warn) prefix = "warning: ";
    else if (msg.level >= spdlog::level::err) prefix = "error: ";
    dest.append(prefix.data(), prefix.data() + prefix.size());
  }
  std::unique_ptr<custom_flag_formatter> clone() const override {
    return std::make_unique<SeverityPrefix>();
  }
};

// Log lines go to stderr, as the progress line does: a live one still open is ended first.
class AfterLiveLine : public spdlog::sinks::sink {
 public:
  explicit AfterLiveLine(std::shared_ptr<spdlog::sinks::sink> stderr_sink) : stderr_(std::move(stderr_sink)) {}
  void log(const spdlog::details::log_msg& msg) override {
    end_live_line();
    stderr_->log(msg);
  }
  void flush() override { stderr_->flush(); }
  void set_pattern(const std::string& pattern) override { stderr_->set_pattern(pattern); }
  void set_formatter(std::unique_ptr<spdlog::formatter> formatter) override {
    stderr_->set_formatter(std::move(formatter));
  }

 private:
  std::shared_ptr<spdlog::sinks::sink> stderr_;
};

// The run layer logs through the default logger; the program decides where and how much.
void configure_logging(Verbosity verbosity) {
  const auto level = verbosity == Verbosity::Quiet     ? spdlog::level::warn
                     : verbosity == Verbosity::Verbose ? spdlog::level::debug
                                                       : spdlog::level::info;
  auto printed = std::make_shared<AfterLiveLine>(std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
  printed->set_level(level);
  auto logger = std::make_shared<spdlog::logger>("hydrodda", printed);
  auto formatter = std::make_unique<spdlog::pattern_formatter>();
  formatter->add_flag<SeverityPrefix>('*').set_pattern("%^%*%$%v");
  logger->set_formatter(std::move(formatter));
  logger->set_level(level);
  // A test's hold point (cli/hold_points.hpp) sees every line, printed or not.
  if (auto hold = make_line_hold_sink()) {
    logger->sinks().push_back(std::move(hold));
    logger->set_level(spdlog::level::trace);
  }
  spdlog::set_default_logger(logger);
}
}  // namespace

// For counts that start at 1 (--jobs, --stop-after, --threads): CLI11's PositiveNumber said "Value 0 not
// in range 0.000000 to 1.79e308".
const CLI::Validator kWholeNumberFromOne(
    [](std::string& value) -> std::string {
      std::size_t used = 0;
      long long n = 0;
      try {
        n = std::stoll(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != value.size() || used == 0 || n < 1) return "must be a whole number >= 1, got " + value;
      return {};
    },
    "INT>=1");

int run_app(int argc, char** argv) {
  CLI::App app{"hydrodda: fluid flow through deforming, fractured, blocky rock (HYDRO-DDA)"};
  app.set_version_flag("--version", std::string("hydrodda ") + kVersion + ", sweeps " + sweep::SweepRanks::build_description());
  app.require_subcommand(1);
  bool quiet = false;
  bool verbose = false;
  app.add_flag("-q,--quiet", quiet, "Print warnings and errors only");
  app.add_flag("-v,--verbose", verbose, "Print every step and every default used");

  RunOptions run;
  std::string output;
  CLI::App* run_cmd = app.add_subcommand("run", "Run a scenario and write its run folder");
  std::string resume;
  CLI::Option* scenario_opt = run_cmd->add_option("scenario", run.scenario, "Scenario file (TOML)");
  CLI::Option* output_opt = run_cmd->add_option("-o,--output", output, "Run folder (default: output.directory)");
  CLI::Option* overwrite_opt = run_cmd->add_flag("--overwrite", run.overwrite,
                                                 "Replace results in a run folder that already holds files");
  CLI::Option* resume_opt = run_cmd->add_option(
      "--resume", resume,
      "Continue the coupled run in this run folder after its last finished coupling iteration, with the "
      "scenario copy saved there (no SCENARIO)");
  int stop_after = 0;
  run_cmd->add_option("--stop-after", stop_after,
                      "Coupled runs: stop after this coupling iteration (a coupled transient run: this time step), resumable "
                      "with --resume")
      ->check(kWholeNumberFromOne);
  std::string mesh_cache;
  CLI::Option* mesh_cache_opt = run_cmd->add_option(
      "--mesh-cache", mesh_cache,
      "A folder of meshes shared between runs: the mesh is read from it when a run with the same geometry and "
      "mesh settings left it there, else stored there (a sweep's cases share one)");
  const char* const threads_help =
      "Threads to use (default: HYDRODDA_THREADS, else every core this process may use); the results are the "
      "same on any number";
  run_cmd->add_option("--threads", run.threads, threads_help)->check(kWholeNumberFromOne);
  resume_opt->excludes(scenario_opt)->excludes(output_opt)->excludes(overwrite_opt)->excludes(mesh_cache_opt);

  std::filesystem::path check_file;
  CLI::App* check_cmd = app.add_subcommand("check", "Validate a scenario without running it");
  check_cmd->add_option("scenario", check_file, "Scenario file (TOML)")->required();
  std::optional<std::filesystem::path> check_figure;
  check_cmd->add_option("--figure", check_figure,
                        "Draw the model as a run would build it (blocks, traces, boundaries and their conditions, "
                        "regions, points, the mesh to expect) into this file: .png, .svg or .pdf");

  SweepOptions sweep;
  std::string sweep_output;
  CLI::App* sweep_cmd = app.add_subcommand("sweep", "Run a scenario for every combination of swept values");
  sweep_cmd->add_option("scenario", sweep.scenario, "Scenario file (TOML)")->required();
  sweep_cmd->add_option("--set", sweep.sets, "KEY=V1,V2,...: a key path of the scenario and its values (repeatable)")
      ->required()
      ->allow_extra_args(false);
  CLI::Option* sweep_output_opt =
      sweep_cmd->add_option("-o,--output", sweep_output, "Sweep folder (default: out/<scenario name>-sweep)");
  sweep_cmd->add_option("--jobs", sweep.jobs, "Cases run at a time (default: the threads)")
      ->check(kWholeNumberFromOne);
  sweep_cmd->add_option("--threads", sweep.threads, "Threads of all the cases at a time, shared between the --jobs "
                        "cases (default: HYDRODDA_THREADS, else every core this process may use)")
      ->check(kWholeNumberFromOne);
  sweep_cmd->add_option("--column", sweep.columns,
                        "A summary.json path to gather, e.g. flow.regions.core.effective_conductivity (repeatable)")
      ->allow_extra_args(false);
  sweep_cmd->add_flag("--overwrite", sweep.overwrite, "Replace results in a sweep folder that already holds files");
  sweep_cmd->add_flag("--zip", sweep.zip,
                      "Take the --set lists together (case i sets every key to its i-th value) instead of "
                      "running every combination");
  sweep_cmd->add_option("--title", sweep.title, "Title of sweep.png (default: the scenario's title)");

  BreachOptions breach;
  std::string breach_output;
  CLI::App* breach_cmd = app.add_subcommand(
      "breach", "Raise one load of a coupled scenario step by step, each from the last state that held, and "
                "bracket the load at which it stops holding");
  breach_cmd->add_option("scenario", breach.scenario, "Scenario file (TOML), coupled")->required();
  breach_cmd->add_option("--vary", breach.keys,
                         "The load's key path: flow.boundary[i].head, .pressure or .flux, or "
                         "mechanics.traction[i].normal or .shear (repeatable: the keys take the same value)")
      ->required()
      ->allow_extra_args(false);
  breach_cmd->add_option("--from", breach.from, "The first load (the key's unit)")->required();
  breach_cmd->add_option("--to", breach.to, "The last load tried when every step holds")->required();
  breach_cmd->add_option("--steps", breach.steps, "Equal steps from --from to --to (default 10)")
      ->check(kWholeNumberFromOne);
  breach_cmd->add_option("--tolerance", breach.tolerance,
                         "The bracket's width once narrowed, as a share of the load (default 0.005)");
  breach_cmd->add_option("--limit", breach.limit,
                         "PATH=VALUE: a state holds only while this summary.json value stays at or below VALUE, e.g. "
                         "flow.regions.seal.normalised_conductivity=100");
  breach_cmd->add_flag("--converged-only", breach.converged_only,
                       "Only a step whose coupling loop converged holds: a step whose blocks came to rest but whose "
                       "loop swung (held, unsettled) is then the breach");
  CLI::Option* breach_output_opt =
      breach_cmd->add_option("-o,--output", breach_output, "Breach folder (default: out/<scenario name>-breach)");
  breach_cmd->add_option("--threads", breach.threads, threads_help)->check(kWholeNumberFromOne);
  breach_cmd->add_flag("--overwrite", breach.overwrite, "Replace results in a breach folder that already holds files");

  for (CLI::App* sub : {run_cmd, check_cmd, sweep_cmd, breach_cmd}) {
    sub->add_flag("-q,--quiet", quiet, "Print warnings and errors only");
    sub->add_flag("-v,--verbose", verbose, "Print every step and every default used");
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kSuccess : kBadInput;
  }

  run.verbosity = quiet ? Verbosity::Quiet : verbose ? Verbosity::Verbose : Verbosity::Normal;
  configure_logging(run.verbosity);
  for (const CLI::Option* o : {output_opt, sweep_output_opt, breach_output_opt})
    if (o->count() > 0 && o->as<std::string>().empty()) {
      spdlog::error("{}: the folder's path is empty", o->get_name());
      return kBadInput;
    }
  if (!output.empty()) run.output = output;
  if (!resume.empty()) run.resume = resume;
  if (!mesh_cache.empty()) run.mesh_cache = mesh_cache;
  if (stop_after > 0) run.stop_after = stop_after;
  if (*run_cmd && run.scenario.empty() && !run.resume) {
    spdlog::error("run: give a SCENARIO file, or --resume DIR to continue a run");
    return kBadInput;
  }

  start_interrupt_thread();  // before any thread (OpenMP's, a sweep's) starts
  if (*check_cmd) {
    set_exit_on_interrupt(true);  // check writes nothing: an interrupt ends it at once
    return check_command(check_file, check_figure);
  }
  if (*breach_cmd) {
    if (!breach_output.empty()) breach.output = breach_output;
    return breach_command(breach);
  }
  if (*sweep_cmd) {
    if (!sweep_output.empty()) sweep.output = sweep_output;
    return sweep_on_ranks(sweep);
  }
  return run_command(run);
}

}  // namespace hydrodda::cli
