#pragma once
// The run layer's entry point: a scenario run into its run folder, and what happened.
//
// run() builds the model the scenario describes (flow only, mechanics only, or coupled, by the
// sections it has), runs it and writes the run folder as it goes; resume() continues a coupled
// or transient flow-only run from its checkpoint. Nothing here prints or exits. Input that cannot be run is an
// exception thrown before anything is run: scenario::ScenarioError (with its diagnostics),
// InputError, output::RunFolderError. Everything after that is a RunResult, a failure included,
// with summary.json written for the last good state.
//
// Logging: informational lines and warnings ("mesh: 7723 nodes, 15234 triangles", a loop that
// did not converge) go to spdlog's default logger, which this layer never configures: the front
// end owns it (its sink, pattern and level), or silences it.

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "output/summary.hpp"
#include "run/resumed_run.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::fractures {
struct FractureState;
}

namespace hydrodda::run {

// What a run reports as it goes: each DDA step of a mechanics-only run, each pass of a coupled
// run, the one solve of a flow-only run.
struct ProgressReport {
  enum class Kind { flow_solve, mechanics_step, coupling_pass };
  Kind kind = Kind::flow_solve;
  long long count = 0;               // the step's or pass's number, from 1 (1 for the flow solve)
  double time = 0.0;                 // mechanics time at its end (s)
  double head_change = 0.0;          // passes: relative change of the heads from the last pass
  double displacement_change = 0.0;  // passes: the blocks' largest move against max(largest displacement, ℓ)
  int contacts = 0;                  // steps: closed contacts at its end
  double max_displacement = 0.0;     // steps: largest vertex displacement in it (m)
  double balance_error = 0.0;        // the flow solve: relative mass-balance error
  std::string message;               // all of it in one line, for people
};

class FlowModel;
class MechanicsModel;
class CoupledModel;

// A run's model as the run ends, for a front end that reads its fields from memory (the Python
// module): the model in its last state (a coupled run's last finished pass) and, when the
// scenario has fracture traces and the run measured them, the fractures' results then.
struct ModelAtEnd {
  std::variant<const FlowModel*, const MechanicsModel*, const CoupledModel*> model;
  const fractures::FractureState* fractures = nullptr;
};

struct Callbacks {
  // Called after every step, pass or solve; unset: nothing is reported.
  std::function<void(const ProgressReport&)> progress;
  // Asked before every DDA step (those inside a coupling pass too), every open–close pass within
  // a step (dda::System::set_interrupt_check) and every pass, and in a
  // flow-only run after its one solve (which is not stopped) and before each of its figures.
  // True stops the run there, with the run folder and summary.json at the last finished step or
  // pass, or a flow run's solution (RunStatus::interrupted). Unset: never.
  // Called on the thread that runs, so a flag a signal handler sets will do.
  std::function<bool()> stop_requested;
  // Called with true before a stage that cannot stop at a stop request and leaves nothing to
  // keep (building the model: meshing, the first flow solve), with false after it: a front end
  // may end the process at once on an interrupt meanwhile. Unset: nothing is said.
  std::function<void(bool)> unstoppable_stage;
  // Called once when a run that built its model ends, whether finished, stopped, interrupted or
  // failed, before the model is destroyed; what it throws is ignored. Unset: nothing is said.
  std::function<void(const ModelAtEnd&)> model_at_end;
};

enum class RunStatus {
  finished,     // ran to its end; `converged` says whether the coupling loop met its tolerance
  stopped,      // a coupled run stopped after RunOptions::stop_after passes, to be resumed
  interrupted,  // Callbacks::stop_requested stopped it
  failed,       // a step, solve or pass failed; `message` says what and where
  // No mechanical equilibrium exists under the load: blocks escape (run/no_equilibrium.hpp);
  // `message` names the load, the blocks and the fractures open at the last state kept.
  no_equilibrium,
};

struct RunResult {
  RunStatus status = RunStatus::finished;
  // The coupling loop met its tolerance; a flow-only or mechanics-only run that reached its end
  // says true (as summary.json does).
  bool converged = false;
  int iterations = 0;             // coupling passes, DDA steps, or 1 for a flow solve
  std::string message;            // why it stopped or failed; empty when finished
  output::RunSummary summary;     // as written to summary.json
  std::filesystem::path folder;
  // A run that failed or was interrupted: summary.json holds a state of its model (the last
  // good one) and every value in it is finite. False where it holds none (the run failed
  // before it had a model) or one with values not finite (written as null).
  bool good_state_kept = false;
};

struct RunOptions {
  std::filesystem::path folder;   // the run folder, made when missing
  // A folder that already holds files is refused (output::RunFolderError), or with `overwrite`
  // its files of the same names are replaced.
  bool overwrite = false;
  std::optional<int> stop_after{};  // coupled runs: stop after this pass, resumable
  // The scenario's text, which a coupled run saves as scenario.toml (for resume); unset: read
  // from scenario.file.
  std::optional<std::string> scenario_text{};
  // A folder of meshes shared with other runs: a generated mesh is read from it when a run with
  // the same geometry and mesh settings has left it there, else stored there (a sweep's cases
  // share one, so that a sweep over heads or loads meshes once).
  std::optional<std::filesystem::path> mesh_cache{};
};

// Input that is not the scenario file's: a run folder that cannot be resumed, an option the
// scenario's kind of run does not take, a scenario file that cannot be read again.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class RunKind { flow, mechanics, coupled };
// Coupled with [mechanics] and [flow], else whichever of the two the scenario has.
RunKind kind_of(const scenario::Scenario& scenario);

// Runs the scenario into options.folder. A scenario::ScenarioError found while building the
// model (a fixed point in no block, a mesh.file Gmsh cannot read) is rethrown after removing
// the folder if this call made it: bad input leaves no run folder behind.
RunResult run(const scenario::Scenario& scenario, const RunOptions& options, const Callbacks& callbacks = {});

// Continues the run of open_resumed_run() in its folder after its last finished pass (coupled)
// or the step of its checkpoint (transient flow-only); it ends where an uninterrupted run does,
// file for file.
RunResult resume(const ResumedRun& resumed, std::optional<int> stop_after, const Callbacks& callbacks = {});

// Removes from a folder of shared meshes (RunOptions::mesh_cache) the files the cache made, and
// nothing else: a sweep starts with no mesh an earlier one (an older program) made, and a file
// of the user's there is kept. Throws output::RunFolderError when it cannot (a symbolic link in
// the folder's place is not followed).
void clear_mesh_cache(const std::filesystem::path& folder);

// The whole content of a file, or nothing when it cannot be read.
std::optional<std::string> read_text_file(const std::filesystem::path& file);

// What only building the model shows (a fixed point in no block, a boundary the mesh file does
// not name, a mesh too large for this machine), short of meshing and running: throws
// scenario::ScenarioError listing it. Returns the traces and blocks the domain is cut into and
// the triangles the mesh is expected to have ("" without a domain).
std::string check_model(const scenario::Scenario& scenario);

}  // namespace hydrodda::run
