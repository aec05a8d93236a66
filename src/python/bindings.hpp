#pragma once
// The pieces of the extension module _hydrodda, each binding one part of the run layer.

#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>

#include "scenario/scenario.hpp"

namespace hydrodda::python {

namespace py = pybind11;

// A scenario as Python sees it: the TOML text, the file it names (the base of relative paths,
// and the name in messages and in summary.json) and the validated definition read from them.
// The text is what a run saves as scenario.toml, so a scenario changed by set() resumes as run.
struct PythonScenario {
  std::string text;
  std::filesystem::path file;
  scenario::Scenario definition;
};

// Reads `text` as `file` holds it; throws scenario::ScenarioError listing every problem.
PythonScenario read_python_scenario(std::string text, const std::filesystem::path& file);

// The scenario with the value at a key path set (as `sweep --set`), read again; throws
// scenario::ScenarioError when the result is not a valid scenario.
PythonScenario with_value(const PythonScenario& scenario, const std::string& key, const py::handle& value);

void bind_errors(py::module_& module);      // ScenarioError, InputError, RunFolderError
void bind_scenario(py::module_& module);    // Scenario, Diagnostic
void bind_run(py::module_& module);         // _run, _resume, ProgressReport
void bind_simulation(py::module_& module);  // Simulation
// spdlog's default logger → Python's logging, logger "hydrodda".
void route_logging_to_python();

}  // namespace hydrodda::python
