// hydrodda.run and hydrodda.resume: the run layer's run() and resume() with the GIL released,
// progress reported to a Python callable and Ctrl-C honoured between steps and passes.

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "breach/breach.hpp"
#include "output/summary.hpp"
#include "python/bindings.hpp"
#include "python/model_fields.hpp"
#include "python/python_callbacks.hpp"
#include "run/resumed_run.hpp"
#include "run/run.hpp"
#include "run/threads.hpp"

namespace hydrodda::python {

namespace {

const char* status_name(run::RunStatus status) {
  switch (status) {
    case run::RunStatus::finished: return "finished";
    case run::RunStatus::stopped: return "stopped";
    case run::RunStatus::interrupted: return "interrupted";
    case run::RunStatus::failed: return "failed";
    case run::RunStatus::no_equilibrium: return "no equilibrium";
  }
  return "";
}

const char* kind_name(run::ProgressReport::Kind kind) {
  switch (kind) {
    case run::ProgressReport::Kind::flow_solve: return "flow_solve";
    case run::ProgressReport::Kind::mechanics_step: return "mechanics_step";
    case run::ProgressReport::Kind::coupling_pass: return "coupling_pass";
  }
  return "";
}

// What run() returned, for the package's RunResult; the summary as summary.json's text.
py::dict result_fields(const run::RunResult& result, const PythonCallbacks& callbacks) {
  py::dict fields;
  fields["status"] = status_name(result.status);
  fields["converged"] = result.converged;
  fields["iterations"] = result.iterations;
  fields["message"] = result.message;
  fields["summary_json"] = output::format_summary(result.summary);
  fields["folder"] = result.folder;
  fields["fields"] = callbacks.fields_at_end();
  return fields;
}

// A breach search's outcome, for the package's BreachResult.
py::dict breach_fields(const breach::BreachOutcome& outcome) {
  const breach::SearchResult& r = outcome.search;
  py::dict fields;
  fields["held"] = r.held ? py::object(py::float_(*r.held)) : py::object(py::none());
  fields["broken"] = r.broken ? py::object(py::float_(*r.broken)) : py::object(py::none());
  fields["broken_status"] = r.broken_status ? py::object(py::str(breach::status_name(*r.broken_status))) : py::object(py::none());
  fields["narrowed"] = r.narrowed;
  fields["interrupted"] = r.interrupted;
  fields["unsettled_held"] = r.unsettled_held;
  fields["verdict"] = outcome.verdict;
  fields["folder"] = outcome.folder;
  py::list steps;
  for (const breach::SearchStep& s : r.steps) {
    py::dict step;
    step["index"] = s.index;
    step["load"] = s.load;
    step["kind"] = s.bisection ? "bisection" : "step";
    step["status"] = breach::status_name(s.result.status);
    step["passes"] = s.result.passes;
    step["message"] = s.result.message;
    steps.append(step);
  }
  fields["steps"] = steps;
  return fields;
}

thread_local PythonCallbacks* current_run = nullptr;  // the innermost run under way on this thread

}  // namespace

PythonCallbacks::PythonCallbacks(py::object progress, bool keep_fields)
    : progress_(std::move(progress)), keep_fields_(keep_fields), enclosing_(current_run) {
  current_run = this;
}

PythonCallbacks::~PythonCallbacks() { current_run = enclosing_; }

bool PythonCallbacks::take_interrupt(py::error_already_set&& error) {
  if (current_run == nullptr) return false;
  if (!current_run->pending_) current_run->pending_.emplace(std::move(error));
  return true;
}

run::Callbacks PythonCallbacks::callbacks() {
  run::Callbacks callbacks;
  if (!progress_.is_none()) {
    callbacks.progress = [this](const run::ProgressReport& report) {
      if (pending_) return;
      py::gil_scoped_acquire gil;
      try {
        progress_(report);
      } catch (py::error_already_set& e) {
        pending_.emplace(std::move(e));
      }
    };
  }
  if (keep_fields_) {
    callbacks.model_at_end = [this](const run::ModelAtEnd& end) {
      py::gil_scoped_acquire gil;
      try {
        fields_at_end_ = python::fields_at_end(end);
      } catch (py::error_already_set& e) {
        if (!pending_) pending_.emplace(std::move(e));
      }
    };
  }
  callbacks.stop_requested = [this] {
    if (pending_) return true;
    py::gil_scoped_acquire gil;
    // Runs Python's signal handlers here, on the main thread: Ctrl-C raises KeyboardInterrupt.
    if (PyErr_CheckSignals() != 0) pending_.emplace();
    return pending_.has_value();
  };
  return callbacks;
}

void PythonCallbacks::raise_pending() {
  if (!pending_) return;
  py::error_already_set error = std::move(*pending_);
  pending_.reset();
  throw error;
}

void bind_run(py::module_& module) {
  py::class_<run::ProgressReport>(module, "ProgressReport", "What a run reports after each step, pass or solve.")
      .def_property_readonly("kind", [](const run::ProgressReport& r) { return kind_name(r.kind); },
                             "'flow_solve', 'mechanics_step' or 'coupling_pass'")
      .def_readonly("count", &run::ProgressReport::count)
      .def_readonly("time", &run::ProgressReport::time)
      .def_readonly("head_change", &run::ProgressReport::head_change)
      .def_readonly("displacement_change", &run::ProgressReport::displacement_change)
      .def_readonly("contacts", &run::ProgressReport::contacts)
      .def_readonly("max_displacement", &run::ProgressReport::max_displacement)
      .def_readonly("balance_error", &run::ProgressReport::balance_error)
      .def_readonly("message", &run::ProgressReport::message)
      .def("__repr__", [](const run::ProgressReport& r) { return "<ProgressReport " + r.message + ">"; });

  module.def(
      "_run",
      [](const PythonScenario& scenario, const std::optional<std::filesystem::path>& folder, bool overwrite,
         std::optional<int> stop_after, py::object progress, std::optional<int> threads) {
        const run::RunOptions options{folder.value_or(scenario.definition.output.directory), overwrite, stop_after,
                                      scenario.text};
        PythonCallbacks callbacks(std::move(progress), /*keep_fields=*/true);
        std::optional<run::RunResult> result;
        {
          py::gil_scoped_release released;
          const run::ThreadsOfThisCall own_threads(threads);
          result = run::run(scenario.definition, options, callbacks.callbacks());
        }
        callbacks.raise_pending();
        return result_fields(*result, callbacks);
      },
      py::arg("scenario"), py::arg("folder"), py::arg("overwrite"), py::arg("stop_after"), py::arg("progress"),
      py::arg("threads"));

  module.def(
      "_resume",
      [](const std::filesystem::path& folder, std::optional<int> stop_after, py::object progress,
         std::optional<int> threads) {
        const run::ResumedRun resumed = run::open_resumed_run(folder);
        PythonCallbacks callbacks(std::move(progress), /*keep_fields=*/true);
        std::optional<run::RunResult> result;
        {
          py::gil_scoped_release released;
          const run::ThreadsOfThisCall own_threads(threads);
          result = run::resume(resumed, stop_after, callbacks.callbacks());
        }
        callbacks.raise_pending();
        return result_fields(*result, callbacks);
      },
      py::arg("folder"), py::arg("stop_after"), py::arg("progress"), py::arg("threads"));

  module.def(
      "_breach",
      [](const PythonScenario& scenario, std::vector<std::string> keys, double start, double stop, int steps,
         double tolerance, std::optional<std::string> limit_path, std::optional<double> limit_value,
         const std::optional<std::filesystem::path>& folder, bool overwrite, std::optional<int> threads,
         bool converged_only) {
        breach::BreachJob job;
        job.scenario = scenario.file;
        job.text = scenario.text;
        job.keys = std::move(keys);
        job.search = {start, stop, steps, tolerance};
        job.search.converged_only = converged_only;
        if (limit_path) job.limit = breach::Limit{*limit_path, limit_value.value_or(0.0)};
        job.directory = folder.value_or(scenario.definition.output.directory.parent_path() /
                                        (scenario.definition.output.directory.filename().string() + "-breach"));
        job.overwrite = overwrite;
        PythonCallbacks callbacks{py::none()};
        std::optional<breach::BreachOutcome> outcome;
        {
          py::gil_scoped_release released;
          const run::ThreadsOfThisCall own_threads(threads);
          outcome = breach::run_breach(job, callbacks.callbacks().stop_requested);
        }
        callbacks.raise_pending();
        return breach_fields(*outcome);
      },
      py::arg("scenario"), py::arg("keys"), py::arg("start"), py::arg("stop"), py::arg("steps"), py::arg("tolerance"),
      py::arg("limit_path"), py::arg("limit_value"), py::arg("folder"), py::arg("overwrite"), py::arg("threads"),
      py::arg("converged_only"));
}

}  // namespace hydrodda::python
