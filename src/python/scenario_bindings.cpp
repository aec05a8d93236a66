// Scenario and Diagnostic, and the exceptions that carry the program's messages.

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "output/run_folder.hpp"
#include "run/run.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/overrides.hpp"
#include "scenario/reader.hpp"
#include "python/bindings.hpp"

namespace hydrodda::python {

namespace {

py::list diagnostics_list(const scenario::ScenarioError& error) {
  py::list list;
  for (const scenario::Diagnostic& d : error.diagnostics()) list.append(py::cast(d));
  return list;
}

// Lists deeper than this are no scenario value (its deepest are lists of points, two levels):
// the conversion recurses, and a list nested 200,000 deep would overflow the stack.
constexpr std::size_t kMaxListDepth = 32;

// `value` as TOML text for apply_overrides: booleans, integers, floats, strings (quoted, so a
// string never reads as a number) and lists of them. `enclosing`: the lists `value` is inside,
// outermost first, to refuse a list that contains itself.
std::string toml_value(const py::handle& value, std::vector<PyObject*>& enclosing) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  if (py::isinstance<py::float_>(value)) {
    const double x = value.cast<double>();
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return py::repr(value).cast<std::string>();  // shortest text that reads back to x
  }
  if (py::isinstance<py::str>(value)) {
    std::string quoted = "\"";
    for (const char c : value.cast<std::string>()) {
      if (c == '"' || c == '\\') quoted += '\\';
      if (c == '\n') { quoted += "\\n"; continue; }
      if (c == '\t') { quoted += "\\t"; continue; }
      quoted += c;
    }
    return quoted + "\"";
  }
  if (py::isinstance<py::sequence>(value)) {
    if (std::find(enclosing.begin(), enclosing.end(), value.ptr()) != enclosing.end())
      throw py::value_error("a list that contains itself is no scenario value");
    if (enclosing.size() >= kMaxListDepth)
      throw py::value_error("lists nested more than " + std::to_string(kMaxListDepth) +
                            " deep are no scenario value");
    enclosing.push_back(value.ptr());
    std::string list = "[";
    // An object, not a handle: a NumPy array's items are made as they are read.
    for (const py::object item : value.cast<py::sequence>())
      list += (list.size() > 1 ? ", " : "") + toml_value(item, enclosing);
    enclosing.pop_back();
    return list + "]";
  }
  // NumPy scalars and other numbers.
  if (py::hasattr(value, "__float__")) {
    PyObject* number = PyNumber_Float(value.ptr());
    if (number == nullptr) throw py::error_already_set();
    return toml_value(py::reinterpret_steal<py::object>(number), enclosing);
  }
  throw py::type_error("a scenario value must be a bool, a number, a string or a list of them, not " +
                       py::str(value.get_type().attr("__name__")).cast<std::string>());
}

// The same, naming the key in a refusal.
std::string toml_value(const std::string& key, const py::handle& value) {
  std::vector<PyObject*> enclosing;
  try {
    return toml_value(value, enclosing);
  } catch (const py::value_error& e) {
    throw py::value_error(key + ": " + e.what());
  }
}

const char* kind_name(run::RunKind kind) {
  switch (kind) {
    case run::RunKind::flow: return "flow";
    case run::RunKind::mechanics: return "mechanics";
    case run::RunKind::coupled: return "coupled";
  }
  return "";
}

}  // namespace

PythonScenario read_python_scenario(std::string text, const std::filesystem::path& file) {
  scenario::Scenario definition = scenario::parse_scenario(text, file);
  return PythonScenario{std::move(text), file, std::move(definition)};
}

PythonScenario with_value(const PythonScenario& scenario, const std::string& key, const py::handle& value) {
  std::string text = scenario::apply_overrides(scenario.text, scenario.file, {{key, toml_value(key, value)}});
  return read_python_scenario(std::move(text), scenario.file);
}

void bind_errors(py::module_& module) {
  static py::exception<scenario::ScenarioError> scenario_error(module, "ScenarioError", PyExc_ValueError);
  static py::exception<run::InputError> input_error(module, "InputError", PyExc_ValueError);
  static py::exception<output::RunFolderError> folder_error(module, "RunFolderError", PyExc_FileExistsError);
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const scenario::ScenarioError& e) {
      // The program's lines ("file:line: key: message"), and each as a Diagnostic.
      py::object instance = py::handle(scenario_error.ptr())(py::str(e.what()));
      instance.attr("diagnostics") = diagnostics_list(e);
      PyErr_SetObject(scenario_error.ptr(), instance.ptr());
    } catch (const run::InputError& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const output::RunFolderError& e) {
      PyErr_SetString(folder_error.ptr(), e.what());
    }
  });
}

void bind_scenario(py::module_& module) {
  py::class_<scenario::Diagnostic>(module, "Diagnostic", "One problem of a scenario, as `hydrodda check` prints it.")
      .def_readonly("file", &scenario::Diagnostic::file)
      .def_readonly("line", &scenario::Diagnostic::line, "0 when no line applies")
      .def_readonly("key", &scenario::Diagnostic::key)
      .def_readonly("message", &scenario::Diagnostic::message)
      .def("__str__", &scenario::Diagnostic::format)
      .def("__repr__", [](const scenario::Diagnostic& d) { return "<Diagnostic " + d.format() + ">"; });

  py::class_<PythonScenario>(module, "Scenario", "A validated scenario and the TOML text it was read from.")
      .def_static(
          "load",
          [](const std::filesystem::path& file) {
            scenario::Scenario definition = scenario::read_scenario(file);  // the program's errors
            std::optional<std::string> text = run::read_text_file(file);
            if (!text) throw scenario::ScenarioError({{file.string(), 0, "", "cannot open the scenario file"}});
            return PythonScenario{std::move(*text), file, std::move(definition)};
          },
          py::arg("path"), "Reads a scenario file; raises ScenarioError listing every problem.")
      .def_static(
          "from_toml",
          [](std::string text, const std::filesystem::path& name) { return read_python_scenario(std::move(text), name); },
          py::arg("text"), py::arg("name") = "scenario.toml",
          "A scenario from TOML text; `name` is the file named in messages and the base of relative paths.")
      .def(
          "set",
          [](PythonScenario& self, const std::string& key, const py::handle& value) {
            self = with_value(self, key, value);  // unchanged if this throws
          },
          py::arg("key"), py::arg("value"),
          "Sets the value at a key path (as `sweep --set`): 'flow.boundary[0].head', 30.0.")
      .def(
          "check",
          [](const PythonScenario& self) {
            try {
              run::check_model(self.definition);
            } catch (const scenario::ScenarioError& e) {
              return diagnostics_list(e);
            }
            return py::list();
          },
          "What building the model finds (`hydrodda check`): a list of Diagnostic, empty when OK.")
      .def("to_toml", [](const PythonScenario& self) { return self.text; }, "The scenario as TOML text.")
      .def("copy", [](const PythonScenario& self) { return self; }, "An independent copy.")
      .def("__copy__", [](const PythonScenario& self) { return self; })
      .def("__deepcopy__", [](const PythonScenario& self, const py::dict&) { return self; })
      .def_property_readonly("file", [](const PythonScenario& self) { return self.file; })
      .def_property_readonly("title", [](const PythonScenario& self) { return self.definition.title; })
      .def_property_readonly("kind", [](const PythonScenario& self) { return kind_name(run::kind_of(self.definition)); },
                             "'flow', 'mechanics' or 'coupled'")
      .def_property_readonly("output_directory",
                             [](const PythonScenario& self) { return self.definition.output.directory; })
      .def("__repr__", [](const PythonScenario& self) {
        return "<Scenario " + self.file.string() + " (" + kind_name(run::kind_of(self.definition)) + ")>";
      });
}

}  // namespace hydrodda::python
